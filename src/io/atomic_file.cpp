// Atomic file writing: temporary file in the same folder, fsync, rename.
#include <tide/io/exporters.hpp>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>


namespace tide::io {

namespace {

/// An output stream buffer over a POSIX file descriptor that remembers the first errno.
class FdStreamBuf : public std::streambuf {
public:
    explicit FdStreamBuf(int fd) : fd_(fd), buffer_(std::size_t{1} << 16) {
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }
    FdStreamBuf(const FdStreamBuf&) = delete;
    FdStreamBuf& operator=(const FdStreamBuf&) = delete;

    /// errno of the first failed write, 0 if none.
    [[nodiscard]] int error() const { return error_; }

protected:
    int_type overflow(int_type ch) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }

    std::streamsize xsputn(const char* s, std::streamsize n) override {
        // Large blocks bypass the buffer.
        if (n >= static_cast<std::streamsize>(buffer_.size())) {
            if (!drain() || !writeAll(s, static_cast<std::size_t>(n))) return 0;
            return n;
        }
        return std::streambuf::xsputn(s, n);
    }

    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const auto n = static_cast<std::size_t>(pptr() - pbase());
        const bool ok = writeAll(pbase(), n);
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return ok;
    }

    bool writeAll(const char* s, std::size_t n) {
        if (error_ != 0) return false;
        while (n > 0) {
            const ssize_t written = ::write(fd_, s, n);
            if (written < 0) {
                if (errno == EINTR) continue;
                error_ = errno;
                return false;
            }
            s += written;
            n -= static_cast<std::size_t>(written);
        }
        return true;
    }

    int fd_;
    std::vector<char> buffer_;
    int error_ = 0;
};

std::string quoted(const std::filesystem::path& p) {
    std::ostringstream s;
    s << p;  // std::quoted form: "dir/name"
    return s.str();
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what, const std::string& reason) {
    std::ostringstream msg;
    msg << "tide::io: cannot write " << quoted(file) << ": " << what << ": " << reason;
    throw std::runtime_error(msg.str());
}

/// Removes the temporary file (and closes its descriptor) unless released.
class TempFileGuard {
public:
    TempFileGuard(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
    TempFileGuard(const TempFileGuard&) = delete;
    TempFileGuard& operator=(const TempFileGuard&) = delete;
    ~TempFileGuard() {
        if (fd_ >= 0) ::close(fd_);
        if (armed_) {
            std::error_code ignored;
            std::filesystem::remove(path_, ignored);
        }
    }
    /// Closes the descriptor, returning errno on failure and 0 on success.
    int close() {
        const int fd = fd_;
        fd_ = -1;
        return ::close(fd) == 0 ? 0 : errno;
    }
    void release() { armed_ = false; }

private:
    std::filesystem::path path_;
    int fd_;
    bool armed_ = true;
};

std::atomic<unsigned> tempCounter{0};

}  // namespace

void writeFileAtomically(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write) {
    if (file.filename().empty()) fail(file, "invalid path", "no file name");

    std::ostringstream tempName;
    // The counter keeps concurrent writers of the same file within this process apart.
    tempName << '.' << file.filename().string() << ".tmp-" << ::getpid() << '-'
             << tempCounter.fetch_add(1, std::memory_order_relaxed);
    const std::filesystem::path temp = file.parent_path() / tempName.str();

    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int err = errno;
        std::ostringstream what;
        what << "cannot create temporary file " << quoted(temp);
        fail(file, what.str(), std::strerror(err));
    }
    TempFileGuard guard(temp, fd);

    {
        FdStreamBuf buffer(fd);
        std::ostream out(&buffer);
        try {
            write(out);
        } catch (const std::exception& e) {
            std::ostringstream msg;
            msg << "tide::io: cannot write " << quoted(file) << ": " << e.what();
            std::throw_with_nested(std::runtime_error(msg.str()));
        }
        out.flush();
        if (buffer.error() != 0) fail(file, "write failed", std::strerror(buffer.error()));
        if (!out) fail(file, "write failed", "output stream error");
    }

    if (::fsync(fd) != 0) {
        const int err = errno;
        fail(file, "fsync failed", std::strerror(err));
    }
    if (const int err = guard.close(); err != 0) fail(file, "close failed", std::strerror(err));

    std::error_code ec;
    std::filesystem::rename(temp, file, ec);
    if (ec) fail(file, "rename failed", ec.message());
    guard.release();

    // Make the rename itself durable; a failure here does not undo a completed write.
    const std::filesystem::path dir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    if (const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dirFd >= 0) {
        (void)::fsync(dirFd);
        ::close(dirFd);
    }
}

}  // namespace tide::io
