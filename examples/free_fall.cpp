// Seed demo 1: a block of water falls, hits the floor, splashes, then waves run through the box.
#include "demo_support.hpp"

int main(int argc, char** argv) {
    const demo::Options options = demo::parse(argc, argv);
    return demo::run(options, [&](tide::Fluid& fluid) {
        demo::initSeedTank(fluid, options);
        fluid.addPoint(glm::vec3(-15, -10, -15), glm::vec3(10, 20, 10), glm::vec3(0, 0, 0));
    });
}
