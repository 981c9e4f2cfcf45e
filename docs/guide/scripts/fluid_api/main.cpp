// The guide's C++ tutorial (docs/guide/fluid-api.md): water in a tank, a block of light oil
// under it that rises, and a jet of heavy oil poured in from the side. Writes the last frame
// as CSV with the columns of `tide run --format csv`, in metres, so the guide's
// plot_frame.py draws it.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <tide/fluid.hpp>

int main(int argc, char** argv) {
    const std::string out = argc > 1 ? argv[1] : "oil_and_water.csv";
    const float seconds = argc > 2 ? std::stof(argv[2]) : 2.0f;

    // dfsph for accuracy; the default, pbf, is for live use (docs/live.md).
    tide::FluidSettings settings;
    settings.solver = tide::FluidSettings::solverNamed("dfsph");

    // World units: 1 unit = 0.025 m (settings.metresPerUnit), so the tank is 1 m wide.
    tide::Fluid fluid;
    fluid.init(40000, {-20, -20, -20}, {20, 20, 20},  // the container
               {-20, -20, -20}, {20, -8, 20},         // water filling its bottom 0.3 m
               {0, -9.81f, 0}, settings);
    // Material(viscosity relative to water, rest density kg/m³, colour).
    const tide::MaterialIndex lightOil = fluid.addMaterial(tide::Material(30.0f, 500.0f, {0.9f, 0.8f, 0.2f}));
    const tide::MaterialIndex heavyOil = fluid.addMaterial(tide::Material(30.0f, 2000.0f, {0.5f, 0.3f, 0.1f}));
    fluid.addPoint({-20, -8, -20}, {-8, 0, 20}, {0, 0, 0}, lightOil);  // a block beside the water's surface

    const float fps = 30.0f;
    const long frames = std::lround(seconds * fps);
    for (long k = 0; k < frames; ++k) {
        if (k < fps) fluid.addPointTick({16, 4, -2}, {16, 8, 2}, {-1.5f, 0, 0}, heavyOil);  // a jet for 1 s
        fluid.step(1.0f / fps);
    }

    // Particle records are in world units; the CSV is in metres, as tide run writes it.
    const float m = fluid.metresPerUnit();
    std::ofstream csv(out);
    csv << "x,y,z,vx,vy,vz,density,pressure,material\n";
    const tide::Point* p = fluid.getPointBuf();
    for (unsigned i = 0; i < fluid.getPointCounts(); ++i) {
        csv << p[i].pos.x * m << ',' << p[i].pos.y * m << ',' << p[i].pos.z * m << ','
            << p[i].vel.x << ',' << p[i].vel.y << ',' << p[i].vel.z << ',' << p[i].density << ','
            << p[i].pressure << ',' << p[i].material << '\n';
    }
    std::printf("%u particles at t = %.2f s written to %s\n", fluid.getPointCounts(), fluid.time(), out.c_str());
    return 0;
}
