// Seed demo 2: one material, two bodies dyed apart. White water fills one corner, red water
// the opposite one; they collide and a wave curls into the white region.
#include "demo_support.hpp"

int main(int argc, char** argv) {
    const demo::Options options = demo::parse(argc, argv);
    return demo::run(options, [&](tide::Fluid& fluid) {
        demo::initSeedTank(fluid, options);
        const tide::MaterialIndex waterRed = fluid.addMaterial(tide::Material(1.0f, 1000.0f, glm::vec3(1, 0.5f, 0.5f)));
        fluid.addPoint(glm::vec3(-20, -20, -20), glm::vec3(0, 0, 0), glm::vec3(0, 0, 0));
        fluid.addPoint(glm::vec3(0, 0, 0), glm::vec3(20, 20, 20), glm::vec3(0, 0, 0), waterRed);
    });
}
