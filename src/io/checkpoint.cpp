// Checkpoint files: encoding, decoding with every count checked, atomic writing.
#include <tide/io/checkpoint.hpp>

#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>

#include <tide/io/exporters.hpp>

namespace tide::io {

namespace {

constexpr char kMagic[8] = {'T', 'I', 'D', 'E', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kByteOrder = 0x01020304u;
constexpr std::size_t kHeaderBytes = sizeof kMagic + 4 + 4 + 8 + 4;

class Writer {
public:
    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    template <class T>
    void putArray(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void putBytes(std::string_view bytes) {
        put<std::uint64_t>(bytes.size());
        bytes_.append(bytes);
    }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
};

class Reader {
public:
    Reader(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}

    template <class T>
    T get(const char* what) {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    template <class T>
    void getArray(std::vector<T>& values, std::uint64_t count, const char* what) {
        if (count > (bytes_.size() - at_) / sizeof(T)) fail(std::string(what) + ": " + std::to_string(count) +
                                                             " values do not fit the bytes left");
        values.resize(count);
        if (count > 0) std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));  // data() may be null
        at_ += count * sizeof(T);
    }
    std::string getBytes(const char* what) {
        const auto count = get<std::uint64_t>(what);
        if (count > bytes_.size() - at_) fail(std::string(what) + ": " + std::to_string(count) + " bytes do not fit the file");
        std::string out(bytes_.substr(at_, count));
        at_ += count;
        return out;
    }
    [[nodiscard]] std::size_t left() const { return bytes_.size() - at_; }
    [[noreturn]] void fail(const std::string& problem) const {
        throw CheckpointError(source_ + ": damaged checkpoint: " + problem);
    }

private:
    void need(std::size_t n, const char* what) const {
        if (n > bytes_.size() - at_) fail(std::string("ends inside ") + what);
    }
    std::string_view bytes_;
    const std::string& source_;
    std::size_t at_ = 0;
};

void putStats(Writer& w, const WorldStats& s) {
    w.put(s.steps);
    w.put(s.lastDt);
    w.put(s.maxSpeed);
    w.put(s.meanDensityError);
    w.put(s.meanCompression);
    w.put(s.emitterCapacityHits);
    w.put<std::int32_t>(s.lastPressureIterations);
    w.put(s.pressureIterationsSum);
    w.put(s.unconvergedSolves);
    w.put(s.recentUnconverged);
    w.put(s.dtMin);
    w.put(s.dtMax);
    w.put(s.dtSum);
    w.put(s.maxMeanDensityError);
    w.put(s.maxMeanCompression);
    w.put(s.sumMeanDensityError);
    const PhaseSeconds& p = s.phaseSeconds;
    for (const double seconds : {p.neighborSearch, p.density, p.pressureSolve, p.nonPressureForces, p.integration})
        w.put(seconds);
    w.put(s.divergenceIterationsSum);
}

WorldStats getStats(Reader& r, std::uint32_t version) {
    WorldStats s;
    s.steps = r.get<std::uint64_t>("stats");
    s.lastDt = r.get<double>("stats");
    s.maxSpeed = r.get<float>("stats");
    s.meanDensityError = r.get<float>("stats");
    s.meanCompression = r.get<float>("stats");
    s.emitterCapacityHits = r.get<std::uint64_t>("stats");
    s.lastPressureIterations = r.get<std::int32_t>("stats");
    s.pressureIterationsSum = r.get<std::uint64_t>("stats");
    if (version >= 3) {
        s.unconvergedSolves = r.get<std::uint64_t>("stats");
        s.recentUnconverged = r.get<std::uint32_t>("stats");
    }
    s.dtMin = r.get<double>("stats");
    s.dtMax = r.get<double>("stats");
    s.dtSum = r.get<double>("stats");
    s.maxMeanDensityError = r.get<float>("stats");
    s.maxMeanCompression = r.get<float>("stats");
    s.sumMeanDensityError = r.get<double>("stats");
    PhaseSeconds& p = s.phaseSeconds;
    for (double* seconds : {&p.neighborSearch, &p.density, &p.pressureSolve, &p.nonPressureForces, &p.integration})
        *seconds = r.get<double>("stats");
    if (version >= 4) s.divergenceIterationsSum = r.get<std::uint64_t>("stats");
    return s;
}

}  // namespace

std::string encodeCheckpoint(const WorldState& s, std::string_view application) {
    Writer payload;
    payload.put(s.time);
    payload.put(s.soundSpeed);
    payload.put(s.stepsSinceReorder);
    putStats(payload, s.stats);
    const ParticleStore& p = s.particles;
    payload.put<std::uint32_t>(p.size());
    payload.put<std::uint32_t>(p.nextId());
    payload.putArray(p.position);
    payload.putArray(p.velocity);
    payload.putArray(p.acceleration);
    payload.putArray(p.density);
    payload.putArray(p.pressure);
    payload.putArray(p.mass);
    payload.putArray(p.warmKappa);
    payload.putArray(p.warmDivergence);
    payload.putArray(p.concentration);
    payload.putArray(p.material);
    payload.putArray(p.id);
    payload.put<std::uint32_t>(static_cast<std::uint32_t>(s.emitters.size()));
    for (const EmitterProgress& e : s.emitters) {
        payload.put<std::uint8_t>(e.active ? 1 : 0);
        payload.put(e.travelled);
    }
    payload.put<std::uint32_t>(static_cast<std::uint32_t>(s.solverState.size()));
    payload.putArray(s.solverState);
    payload.put<std::uint32_t>(static_cast<std::uint32_t>(s.bodyState.size()));
    payload.putArray(s.bodyState);
    payload.put<std::uint32_t>(static_cast<std::uint32_t>(s.paddleState.size()));
    payload.putArray(s.paddleState);
    payload.put(s.stats.oceanAdded);
    payload.put(s.stats.oceanRemoved);
    payload.putBytes(application);

    Writer file;
    file.bytes().append(kMagic, sizeof kMagic);
    file.put(kCheckpointVersion);
    file.put(kByteOrder);
    file.put<std::uint64_t>(payload.bytes().size());
    file.put(crc32(payload.bytes()));
    file.bytes() += payload.bytes();
    return std::move(file.bytes());
}

Checkpoint decodeCheckpoint(std::string_view bytes, const std::string& source) {
    Reader header(bytes, source);
    if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw CheckpointError(source + ": not a tide checkpoint (no TIDECKPT header)");
    for (std::size_t k = 0; k < sizeof kMagic; ++k) header.get<char>("the header");
    const auto version = header.get<std::uint32_t>("the header");
    if (version < kOldestCheckpointVersion || version > kCheckpointVersion)
        throw CheckpointError(source + ": checkpoint format version " + std::to_string(version) + ", this tide reads " +
                              std::to_string(kOldestCheckpointVersion) + " to " + std::to_string(kCheckpointVersion));
    if (header.get<std::uint32_t>("the header") != kByteOrder)
        throw CheckpointError(source + ": checkpoint written on a machine of another byte order");
    const auto size = header.get<std::uint64_t>("the header");
    const auto crc = header.get<std::uint32_t>("the header");
    if (size != header.left())
        header.fail("truncated or padded: the header announces " + std::to_string(size) + " bytes of state, the file has " +
                    std::to_string(header.left()));
    const std::string_view payload = bytes.substr(kHeaderBytes);
    if (crc32(payload) != crc) header.fail("checksum mismatch (the file was changed or corrupted after it was written)");

    Reader r(payload, source);
    Checkpoint c;
    WorldState& s = c.world;
    s.time = r.get<double>("time");
    s.soundSpeed = r.get<float>("sound speed");
    s.stepsSinceReorder = r.get<std::int32_t>("reorder counter");
    s.stats = getStats(r, version);
    ParticleStore& p = s.particles;
    const auto n = r.get<std::uint32_t>("particle count");
    p.setNextId(r.get<std::uint32_t>("next id"));
    r.getArray(p.position, n, "positions");
    r.getArray(p.velocity, n, "velocities");
    r.getArray(p.acceleration, n, "accelerations");
    r.getArray(p.density, n, "densities");
    r.getArray(p.pressure, n, "pressures");
    r.getArray(p.mass, n, "masses");
    r.getArray(p.warmKappa, n, "warmKappa");
    r.getArray(p.warmDivergence, n, "warmDivergence");
    r.getArray(p.concentration, n, "concentrations");
    r.getArray(p.material, n, "materials");
    r.getArray(p.id, n, "ids");
    const auto emitters = r.get<std::uint32_t>("emitter count");
    if (emitters > r.left() / 9) r.fail(std::to_string(emitters) + " emitters do not fit the bytes left");
    s.emitters.resize(emitters);
    for (EmitterProgress& e : s.emitters) {
        e.active = r.get<std::uint8_t>("emitters") != 0;
        e.travelled = r.get<double>("emitters");
    }
    r.getArray(s.solverState, r.get<std::uint32_t>("solver scalar count"), "solver scalars");
    if (version >= 5) r.getArray(s.bodyState, r.get<std::uint32_t>("body scalar count"), "body state");
    if (version >= 6) r.getArray(s.paddleState, r.get<std::uint32_t>("wave maker scalar count"), "wave maker state");
    if (version >= 7) {
        s.stats.oceanAdded = r.get<std::uint64_t>("ocean exchange");
        s.stats.oceanRemoved = r.get<std::uint64_t>("ocean exchange");
    }
    c.application = r.getBytes("application block");
    if (r.left() != 0) r.fail(std::to_string(r.left()) + " bytes after the end of the state");
    return c;
}

void writeCheckpoint(const std::filesystem::path& file, const WorldState& world, std::string_view application) {
    const std::string bytes = encodeCheckpoint(world, application);
    writeFileAtomically(file, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

Checkpoint readCheckpoint(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw CheckpointError(file.string() + ": cannot open the checkpoint");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) throw CheckpointError(file.string() + ": cannot read the checkpoint");
    return decodeCheckpoint(bytes.str(), file.string());
}

}  // namespace tide::io
