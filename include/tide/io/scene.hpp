#pragma once
/// \file
/// Scenes in files (JSON, SI units; see docs/scene-format.md and scenes/scene.schema.json).
/// Parsing reports every problem it finds, each naming its JSON path and value, and never
/// fills in a silent default for a misspelled key.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <tide/defs.hpp>
#include <tide/io/exporters.hpp>
#include <tide/ocean.hpp>
#include <tide/world.hpp>

namespace tide::io {

/// What `tide run` writes and how often.
struct OutputDef {
    double fps = 30.0;                        ///< frames per simulated second
    std::vector<Format> formats{Format::Vtu};
    /// An ocean scene's far field in obj frames (`output.far_field`): how far its mesh reaches
    /// beyond the near field and its points' spacing, m; 0 picks the default
    /// (io::defaultFarFieldExtent, io::defaultFarFieldSpacing). farField false: none.
    bool farField = true;
    double farFieldExtent = 0.0, farFieldSpacing = 0.0;
};

/// Where renderers look from (scene key `camera`), in metres.
struct CameraDef {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f};
    float fovDegrees = 45.0f;                 ///< vertical field of view
};

/// A wave gauge: the free-surface height y at (x, z), written to gauges.csv every frame.
struct GaugeDef {
    std::string name;
    float x = 0.0f;  ///< m
    float z = 0.0f;  ///< m
};

/// A probe: pressure and velocity at a point, written to probes.csv every frame.
struct ProbeDef {
    std::string name;
    glm::vec3 position{0.0f};  ///< m
};

/// A parsed, validated scene. Lengths are already scaled to metres (`unit_scale`).
struct Scene {
    std::string name;
    WorldDef world;
    double endTime = 1.0;                     ///< s
    double settleTime = 0.0;                  ///< s, key "settle.time": World::settle before the run (0: none)
    float settleSpeed = 0.0f;                 ///< m/s, key "settle.speed": World::settle's quiet speed (0: the whole time)
    std::vector<MaterialDef> materials;
    std::vector<MaterialPairDef> materialPairs;  ///< key "material_pairs", material indices resolved from names
    std::vector<ObstacleDef> obstacles;
    std::vector<BlockDef> blocks;             ///< material indices resolved from names
    std::vector<EmitterDef> emitters;
    std::vector<WaveMakerDef> waveMakers;     ///< key "wavemaker"
    std::vector<DampingZoneDef> dampingZones; ///< key "damping"
    std::optional<OceanDef> ocean;            ///< key "ocean": the far-field sea (issue 43)
    std::vector<GaugeDef> gauges;
    std::vector<ProbeDef> probes;
    OutputDef output;
    std::optional<CameraDef> camera;          ///< empty: renderers choose a view of the container
};

/// Bad input: one line per problem, "path: message" or "file:line:column: message".
class SceneError : public std::runtime_error {
public:
    explicit SceneError(std::vector<std::string> problems);
    std::vector<std::string> problems;
};

/// Parse scene text; `source` names it in messages, and files it names (mesh obstacles)
/// are relative to `baseDirectory` (default: the current directory). Throws SceneError.
Scene parseScene(std::string_view json, const std::string& source, const std::filesystem::path& baseDirectory = {});
/// Read and parse a scene file; files it names are relative to its folder. Throws SceneError
/// (also for an unreadable file).
Scene loadScene(const std::filesystem::path& file);

/// How big a scene gets.
struct SceneEstimate {
    std::vector<std::uint64_t> initialParticles;  ///< per material, from blocks
    std::vector<std::uint64_t> emittedParticles;  ///< per material, by end_time
    std::uint64_t totalParticles = 0;
    std::uint64_t bytes = 0;                      ///< peak memory, estimated
};
SceneEstimate estimate(const Scene& scene);
/// Bytes of memory one particle costs (state, neighbour lists, grid, solver arrays), for
/// estimates: peak RSS of `tide run` grew by ~920 B per particle from 12 000 to 50 653
/// particles with dfsph (~650 with wcsph/pcisph; docs/robustness.md). It was 320, which let a
/// scene three times too big for the machine through.
inline constexpr std::uint64_t kBytesPerParticle = 1024;

/// Most frames a run may write (frame numbers are ints).
inline constexpr double kMaxFrames = 1e8;
/// Frames a run writes after frame 0: frame k at k/fps for k = 1 … ⌊end_time · fps⌋. The run
/// stops at the last of them. Meaningful when endTimeProblem(scene) is empty.
int framesAfterTheFirst(const Scene& scene);
/// Empty when end_time reaches frame 1 and asks for at most kMaxFrames frames; otherwise why
/// not: "0.05 s is shorter than one frame at output.fps 10 (0.1 s): nothing would be simulated".
std::string endTimeProblem(const Scene& scene);
/// Empty when end_time lands on a frame; otherwise where the run stops short of it:
/// "0.25 s is not a whole number of frames at output.fps 10: the run stops at frame 2, t = 0.2 s".
std::string endTimeBetweenFrames(const Scene& scene);

/// Memory this machine can still give, bytes (MemAvailable).
std::uint64_t availableMemoryBytes();
/// Empty when the scene (up to its end time) fits in availableMemoryBytes(); otherwise why
/// not, with the estimate: "the scene needs about N particles and M MiB, more than ...".
std::string memoryShortfall(const Scene& scene);

/// Create the world a scene describes: materials, obstacles, wave makers, damping zones, blocks, emitters.
World buildWorld(const Scene& scene);
/// buildWorld, then World::settle for the scene's settle.time (when > 0): the world a run
/// starts from.
World buildSettledWorld(const Scene& scene);

}  // namespace tide::io
