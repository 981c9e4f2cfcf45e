// Replays a failed parse through nlohmann's SAX interface, which reports the error at the value
// it stopped on, keeping the stack of keys and array indices that leads there.
#include "json_error_path.hpp"

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

namespace tide::io {
namespace {

using json = nlohmann::json;

class PathTracker : public nlohmann::json_sax<json> {
public:
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override {
        value();
        frames_.push_back({false, {}, 0, 0});
        return true;
    }
    bool key(string_t& k) override {
        frames_.back().key = k;
        return true;
    }
    bool end_object() override { return pop(); }
    bool start_array(std::size_t) override {
        value();
        frames_.push_back({true, {}, 0, 0});
        return true;
    }
    bool end_array() override { return pop(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        path_.clear();
        for (std::size_t k = 0; k < frames_.size(); ++k) {
            const Frame& f = frames_[k];
            // The innermost array's failing element has not been counted yet.
            const std::size_t index = k + 1 == frames_.size() ? f.next : f.current;
            if (f.array) {
                path_ += '[';
                path_ += std::to_string(index);
                path_ += ']';
            } else if (!f.key.empty()) {
                if (!path_.empty()) path_ += '.';
                path_ += f.key;
            }
        }
        return false;
    }
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    struct Frame {
        bool array;
        std::string key;
        std::size_t current;  ///< arrays: the element being read
        std::size_t next;     ///< arrays: the index the next element gets
    };
    bool value() {
        if (!frames_.empty() && frames_.back().array) frames_.back().current = frames_.back().next++;
        return true;
    }
    bool pop() {
        frames_.pop_back();
        return true;
    }
    std::vector<Frame> frames_;
    std::string path_;
};

}  // namespace

std::string jsonPathWhereParsingStops(std::string_view text) {
    PathTracker tracker;
    json::sax_parse(text.begin(), text.end(), &tracker);
    return tracker.path();
}

}  // namespace tide::io
