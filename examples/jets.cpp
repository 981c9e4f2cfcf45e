// Seed demo 5: a jet through a small outlet on the left wall (--speed 2 or 3 m/s), or four
// jets of four materials at once (--four).
#include "demo_support.hpp"

int main(int argc, char** argv) {
    const demo::Options options = demo::parse(argc, argv);
    const glm::vec3 v(options.speed, 0, 0);
    const auto tank = [&](tide::Fluid& fluid) { demo::initSeedTank(fluid, options); };
    if (!options.four) {
        return demo::run(options, tank, [&](tide::Fluid& f) {
            f.addPointTick(glm::vec3(-20, -4, -4), glm::vec3(-20, 0, 0), v);
        });
    }
    // Set again on every reset (the same indices each time: materials are added in order).
    tide::MaterialIndex heavyOil = 0, lightOil = 0, lightWater = 0;
    const auto setup = [&](tide::Fluid& fluid) {
        tank(fluid);
        heavyOil = fluid.addMaterial(tide::Material(30.0f, 5000.0f, glm::vec3(0.5f, 0.5f, 1)));
        lightOil = fluid.addMaterial(tide::Material(30.0f, 200.0f, glm::vec3(0.5f, 1, 0.5f)));
        lightWater = fluid.addMaterial(tide::Material(1.0f, 200.0f, glm::vec3(1, 0.5f, 0.5f)));
    };
    return demo::run(options, setup, [&](tide::Fluid& f) {
        f.addPointTick(glm::vec3(-20, -4, 4), glm::vec3(-20, 0, 8), v, lightWater);
        f.addPointTick(glm::vec3(-20, -4, -8), glm::vec3(-20, 0, -4), v, lightOil);
        f.addPointTick(glm::vec3(-20, 4, -4), glm::vec3(-20, 8, 0), v, heavyOil);
        f.addPointTick(glm::vec3(-20, -4, -4), glm::vec3(-20, 0, 0), v);
    });
}
