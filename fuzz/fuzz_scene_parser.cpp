// libFuzzer target: the scene parser (any bytes must give a Scene or a SceneError, nothing
// else), then the size estimate and, for small scenes, building the World they describe.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include <tide/io/scene.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    tide::io::Scene scene;
    try {
        scene = tide::io::parseScene(text, "fuzz", TIDE_SCENES_DIR);
    } catch (const tide::io::SceneError&) {
        return 0;
    }
    // Building allocates for every particle: only scenes a test would build.
    if (tide::io::estimate(scene).bytes > (std::uint64_t{16} << 20)) return 0;
    try {
        tide::World world = tide::io::buildWorld(scene);
        (void)world.particles().size();
    } catch (const tide::io::SceneError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
