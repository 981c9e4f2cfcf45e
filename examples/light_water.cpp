// Seed demo 3: "light water" (200 kg/m³) in one slab between two slabs of water; the light
// fluid is squeezed to the top and ends up floating on the water.
#include "demo_support.hpp"

int main(int argc, char** argv) {
    const demo::Options options = demo::parse(argc, argv);
    return demo::run(options, [&](tide::Fluid& fluid) {
        demo::initSeedTank(fluid, options);
        const tide::MaterialIndex lightWater = fluid.addMaterial(tide::Material(1.0f, 200.0f, glm::vec3(1, 0.5f, 0.5f)));
        fluid.addPoint(glm::vec3(-20, -20, -10), glm::vec3(0, 0, 0), glm::vec3(0, 0, 0), lightWater);
        fluid.addPoint(glm::vec3(-20, -20, -20), glm::vec3(0, 0, -10), glm::vec3(0, 0, 0));
        fluid.addPoint(glm::vec3(-20, -20, 0), glm::vec3(0, 0, 20), glm::vec3(0, 0, 0));
    });
}
