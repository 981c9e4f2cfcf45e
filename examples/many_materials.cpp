// Seed demo 4: heavy oil (5000 kg/m³, 30× viscosity), light oil (200, 30×), light water
// (200) and water collide and layer by density.
#include "demo_support.hpp"

int main(int argc, char** argv) {
    const demo::Options options = demo::parse(argc, argv);
    return demo::run(options, [&](tide::Fluid& fluid) {
        demo::initSeedTank(fluid, options);
        const tide::MaterialIndex heavyOil = fluid.addMaterial(tide::Material(30.0f, 5000.0f, glm::vec3(0.5f, 0.5f, 1)));
        const tide::MaterialIndex lightOil = fluid.addMaterial(tide::Material(30.0f, 200.0f, glm::vec3(0.5f, 1, 0.5f)));
        const tide::MaterialIndex lightWater = fluid.addMaterial(tide::Material(1.0f, 200.0f, glm::vec3(1, 0.5f, 0.5f)));
        fluid.addPoint(glm::vec3(-20, -20, 0), glm::vec3(0, 0, 10), glm::vec3(0, 0, 0), lightOil);
        fluid.addPoint(glm::vec3(-20, -20, -20), glm::vec3(0, 0, -10), glm::vec3(0, 0, 0), lightWater);
        fluid.addPoint(glm::vec3(0, 0, 0), glm::vec3(20, 20, 20), glm::vec3(0, 0, 0), heavyOil);
        fluid.addPoint(glm::vec3(0, -20, -20), glm::vec3(20, -10, 0), glm::vec3(0, 0, 0));
    });
}
