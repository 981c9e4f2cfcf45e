#include "run_checkpoints.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <regex>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "comm/particle_records.hpp"
#include "core/world_distributed.hpp"

namespace tide::cli {

namespace fs = std::filesystem;

std::string encodeRunProgress(const RunProgress& p) {
    nlohmann::ordered_json j;
    j["frame"] = p.frame;
    j["particle_steps"] = p.particleSteps;
    j["lost"] = p.lost;
    j["wall_seconds"] = p.wallSeconds;
    j["gauge_rows"] = p.gaugeRows;
    j["probe_rows"] = p.probeRows;
    j["force_rows"] = p.forceRows;
    j["body_rows"] = p.bodyRows;
    j["scene_crc32"] = p.sceneCrc;
    j["solver"] = p.solver;
    j["checkpoint_every"] = p.checkpointEvery;
    j["end_time"] = p.endTime;
    j["formats"] = p.formats;
    j["pieces"] = p.pieces;
    return j.dump();
}

RunProgress decodeRunProgress(const std::string& text) {
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        RunProgress p;
        p.frame = j.at("frame").get<int>();
        p.particleSteps = j.at("particle_steps").get<std::uint64_t>();
        p.lost = j.at("lost").get<std::uint32_t>();
        p.wallSeconds = j.at("wall_seconds").get<double>();
        p.gaugeRows = j.at("gauge_rows").get<std::string>();
        p.probeRows = j.at("probe_rows").get<std::string>();
        p.forceRows = j.value("force_rows", std::string());
        p.bodyRows = j.value("body_rows", std::string());
        p.sceneCrc = j.at("scene_crc32").get<std::uint32_t>();
        p.solver = j.at("solver").get<std::string>();
        p.checkpointEvery = j.at("checkpoint_every").get<int>();
        p.endTime = j.at("end_time").get<double>();
        p.formats = j.at("formats").get<std::vector<std::string>>();
        p.pieces = j.value("pieces", 1);  // absent before split runs wrote checkpoints: one file
        if (p.frame < 0 || p.checkpointEvery < 0 || p.pieces < 1)
            throw std::runtime_error("the run's progress block is unreadable (negative frame or interval, or no pieces)");
        return p;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(std::string("the run's progress block is unreadable (") + e.what() + ")");
    }
}

fs::path checkpointFile(const fs::path& dir, int frame) {
    char name[48];
    std::snprintf(name, sizeof name, "checkpoint_%05d.tidecp", frame);
    return dir / name;
}

fs::path checkpointPiece(const fs::path& dir, int frame, int rank) {
    char name[64];
    std::snprintf(name, sizeof name, "checkpoint_%05d_r%d.tidecp", frame, rank);
    return dir / name;
}

std::vector<fs::path> listCheckpoints(const fs::path& dir) {
    static const std::regex pattern(R"(checkpoint_(\d{5,})\.tidecp)");
    std::vector<std::pair<long long, fs::path>> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        std::smatch m;
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, m, pattern) && m[1].length() < 12) found.emplace_back(std::stoll(m[1]), entry.path());
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<fs::path> files;
    for (auto& f : found) files.push_back(std::move(f.second));
    return files;
}

void pruneCheckpoints(const fs::path& dir) {
    const std::vector<fs::path> files = listCheckpoints(dir);
    std::error_code ignored;
    for (std::size_t k = 2; k < files.size(); ++k) fs::remove(files[k], ignored);
    // Pieces whose main file is gone or was never written.
    std::vector<std::string> kept;
    for (std::size_t k = 0; k < std::min<std::size_t>(2, files.size()); ++k) kept.push_back(files[k].stem().string());
    static const std::regex piece(R"((checkpoint_\d{5,})_r\d+\.tidecp)");
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(dir, ignored)) {
        std::smatch m;
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, m, piece) && std::find(kept.begin(), kept.end(), m[1].str()) == kept.end())
            stale.push_back(entry.path());
    }
    for (const fs::path& f : stale) fs::remove(f, ignored);
}

WorldState joinCheckpointPieces(WorldState main, const std::vector<WorldState>& pieces) {
    ParticleStore& all = main.particles;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const WorldState& piece = pieces[k];
        if (piece.time != main.time || piece.stats.steps != main.stats.steps)
            throw std::runtime_error("piece " + std::to_string(k + 1) + " was saved at step " +
                                     std::to_string(piece.stats.steps) + ", the main file at step " +
                                     std::to_string(main.stats.steps));
        std::vector<std::uint32_t> every(piece.particles.size());
        std::iota(every.begin(), every.end(), 0u);
        comm::appendPacked(all, comm::packParticles(piece.particles, every));
        all.setNextId(std::max(all.nextId(), piece.particles.nextId()));
    }
    sortById(all);
    return main;
}

}  // namespace tide::cli
