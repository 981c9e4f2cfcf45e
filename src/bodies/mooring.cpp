/// \file
/// Mooring lines. A spring with slack pulls only while stretched beyond its length. A
/// catenary is the quasi-static elastic catenary of Jonkman 2007 (NREL/TP-500-41958, §2.2,
/// the single-line model of FAST and MAP; after Irvine 1981, "Cable structures"): given the
/// fairlead's horizontal span and rise over the anchor, the horizontal tension H and the
/// fairlead's vertical tension V solve eqs. (2-1, 2-2) for a freely hanging line, or (2-3, 2-4)
/// with part of the line resting on the seabed (no seabed friction, C_B = 0), by Newton's
/// method from the initial guess of Peyrot & Goulois 1979 (as FAST does). The two forms meet
/// with equal first derivatives at V = wL, so Newton crosses between them smoothly.

#include "bodies/mooring.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bodies/checks.hpp"

namespace tide::bodies {

void validateMooring(const MooringDef& def, const std::string& path) {
    requireFiniteD(path + ".fairlead", def.fairlead);
    requireFiniteD(path + ".anchor", def.anchor);
    requirePositiveD(path + ".length", def.length);
    if (def.type == MooringDef::Type::Spring) {
        requirePositiveD(path + ".stiffness", def.stiffness);
        requireNonNegativeD(path + ".damping", def.damping);
    } else {
        requirePositiveD(path + ".axial_stiffness", def.axialStiffness);
        requirePositiveD(path + ".weight_per_length", def.weightPerLength);
    }
}

namespace {

struct CatenaryResidual {
    double x, z;              // span and rise the (H, V) line reaches
    double xH, xV, zH, zV;    // their derivatives
};

// Jonkman 2007 eqs. (2-1, 2-2) (hanging freely) and (2-3, 2-4) (resting on the seabed, C_B = 0).
CatenaryResidual catenaryShape(double H, double V, double L, double EA, double w) {
    CatenaryResidual r{};
    const double a = V / H;
    const double sa = std::sqrt(1.0 + a * a);
    if (V >= w * L) {  // no seabed contact
        const double b = (V - w * L) / H;
        const double sb = std::sqrt(1.0 + b * b);
        r.x = H / w * (std::asinh(a) - std::asinh(b)) + H * L / EA;
        r.z = H / w * (sa - sb) + (V * L - 0.5 * w * L * L) / EA;
        r.xH = (std::asinh(a) - std::asinh(b)) / w - (a / sa - b / sb) / w + L / EA;
        r.xV = (1.0 / sa - 1.0 / sb) / w;
        r.zH = (1.0 / sa - 1.0 / sb) / w;
        r.zV = (a / sa - b / sb) / w + L / EA;
    } else {  // the bottom L − V/w of the line lies on the seabed
        r.x = L - V / w + H / w * std::asinh(a) + H * L / EA;
        r.z = H / w * (sa - 1.0) + V * V / (2.0 * EA * w);
        r.xH = std::asinh(a) / w - a / (w * sa) + L / EA;
        r.xV = -1.0 / w + 1.0 / (w * sa);
        r.zH = (1.0 / sa - 1.0) / w;
        r.zV = a / (w * sa) + V / (EA * w);
    }
    return r;
}

}  // namespace

std::array<double, 2> solveCatenary(double span, double rise, double L, double EA, double w) {
    requirePositiveD("catenary.length", L);
    requirePositiveD("catenary.axial_stiffness", EA);
    requirePositiveD("catenary.weight_per_length", w);
    requireNonNegativeD("catenary.span", span);
    if (!(rise > 0.0)) throw std::invalid_argument("catenary: the fairlead must be above the anchor, rise " + showd(rise));
    // Slack: the line hanging straight down from the fairlead, V/w of it (stretched: rise =
    // V/w + V²/(2 EA w), eq. 2-4 at H → 0), still leaves the span to lie on the seabed. With no
    // seabed friction nothing pulls it sideways: H = 0.
    const double hanging = EA * (std::sqrt(1.0 + 2.0 * w * rise / EA) - 1.0);
    if (span <= L - hanging / w) return {0.0, hanging};
    const double x = span, z = rise;
    // Peyrot & Goulois 1979 initial guess.
    const double chord2 = x * x + z * z;
    double lambda = chord2 >= L * L ? 0.2 : std::sqrt(3.0 * ((L * L - z * z) / (x * x) - 1.0));
    lambda = std::max(lambda, 1e-3);
    double H = std::max(std::abs(w * x / (2.0 * lambda)), 1e-9 * w * L);
    double V = 0.5 * w * (z / std::tanh(lambda) + L);
    const double tol = 1e-10 * (L + std::sqrt(chord2));
    // Newton in (ln H, V): H stays positive, and a slack line's small H is reached in a few
    // steps; a step that does not lower the residual is halved.
    for (int it = 0; it < 200; ++it) {
        const CatenaryResidual r = catenaryShape(H, V, L, EA, w);
        const double ex = r.x - x, ez = r.z - z;
        if (std::abs(ex) < tol && std::abs(ez) < tol) return {H, V};
        const double j00 = r.xH * H, j10 = r.zH * H;  // d/d(ln H)
        const double det = j00 * r.zV - r.xV * j10;
        const double du = std::clamp(-(r.zV * ex - r.xV * ez) / det, -2.0, 2.0);
        const double dV = -(-j10 * ex + j00 * ez) / det;
        const double e0 = ex * ex + ez * ez;
        double scale = 1.0, Hn = H, Vn = V;
        for (int bt = 0; bt < 60; ++bt) {
            Hn = H * std::exp(scale * du);
            Vn = V + scale * dV;
            const CatenaryResidual t = catenaryShape(Hn, Vn, L, EA, w);
            const double e1 = (t.x - x) * (t.x - x) + (t.z - z) * (t.z - z);
            if (e1 < e0) break;
            scale *= 0.5;
        }
        if (Hn == H && Vn == V) break;  // no progress possible
        H = Hn;
        V = Vn;
        if (!std::isfinite(H) || !std::isfinite(V)) break;
    }
    throw std::runtime_error("catenary: Newton's method did not converge (span " + showd(span) + " m, rise " +
                             showd(rise) + " m, length " + showd(L) + " m)");
}

MooringReading mooringLoad(const MooringDef& def, const glm::dvec3& fairlead, const glm::dvec3& fairleadVelocity,
                           const glm::dvec3& up) {
    MooringReading out;
    const glm::dvec3 d = fairlead - def.anchor;
    if (def.type == MooringDef::Type::Spring) {
        const double ell = glm::length(d);
        if (ell <= def.length || ell == 0.0) return out;  // slack
        const glm::dvec3 e = d / ell;
        const double rate = glm::dot(fairleadVelocity, e);
        out.tension = std::max(0.0, def.stiffness * (ell - def.length) + def.damping * rate);
        out.force = -out.tension * e;
    } else {
        const double rise = glm::dot(d, up);
        const glm::dvec3 horizontal = d - rise * up;
        const double span = glm::length(horizontal);
        const auto [H, V] = solveCatenary(span, rise, def.length, def.axialStiffness, def.weightPerLength);
        const glm::dvec3 towardAnchor = span > 0.0 ? -horizontal / span : glm::dvec3(0.0);
        out.force = H * towardAnchor - V * up;
        out.tension = std::sqrt(H * H + V * V);
    }
    const double vertical = glm::dot(out.force, up);
    out.verticalTension = std::abs(vertical);
    out.horizontalTension = glm::length(out.force - vertical * up);
    return out;
}

double mooringStiffness(const MooringDef& def) {
    // A catenary is never stiffer than its straight elastic chord, EA/L.
    return def.type == MooringDef::Type::Spring ? def.stiffness : def.axialStiffness / def.length;
}

double mooringDamping(const MooringDef& def) { return def.type == MooringDef::Type::Spring ? def.damping : 0.0; }

}  // namespace tide::bodies
