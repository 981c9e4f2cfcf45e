// Uses only the installed public headers: fills a block and lets it fall for a moment.
#include <cstdio>

#include <tide/fluid.hpp>

int main() {
    tide::Fluid fluid;
    fluid.init(4096, {-10, -10, -10}, {10, 10, 10}, {-5, -10, -5}, {5, 0, 5}, {0, -9.81f, 0});
    const unsigned before = fluid.getPointCounts();
    fluid.step(1.0f / 60.0f);
    std::printf("%u particles, t = %.4f s\n", fluid.getPointCounts(), fluid.time());
    return before == 1000 && fluid.getPointCounts() == before && fluid.time() > 0.016 ? 0 : 1;
}
