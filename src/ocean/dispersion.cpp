#include "ocean/dispersion.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tide::ocean {

double waveNumber(double omega, double depth, double g) {
    if (!(omega > 0.0 && std::isfinite(omega)) || !(depth > 0.0 && std::isfinite(depth)) ||
        !(g > 0.0 && std::isfinite(g))) {
        std::ostringstream message;
        message << "ocean::waveNumber: omega, depth and g must be > 0 and finite, got " << omega << ", " << depth
                << ", " << g;
        throw std::invalid_argument(message.str());
    }
    const double x = omega * std::sqrt(depth / g);
    double k = omega * omega / g / std::pow(std::tanh(std::pow(x, 1.5)), 2.0 / 3.0);
    // f is increasing and convex in k: from above, Newton converges monotonically; a start
    // below overshoots once and then does the same. It stops when a step no longer shrinks k.
    for (int iteration = 0; iteration < 50; ++iteration) {
        const double kd = k * depth;
        const double t = std::tanh(kd);
        const double sech = 1.0 / std::cosh(kd);
        const double f = g * k * t - omega * omega;
        const double df = g * t + g * kd * sech * sech;
        const double step = f / df;
        k -= step;
        if (std::abs(step) <= 4.0 * 2.2e-16 * k) break;
    }
    return k;
}

double angularFrequency(double k, double depth, double g) { return std::sqrt(g * k * std::tanh(k * depth)); }

}  // namespace tide::ocean
