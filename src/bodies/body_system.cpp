/// \file
/// Bodies with contact. Why our own penalty contact rather than Bullet (libbullet-dev 3.24):
/// the fluid sets the step (variable, ~1e-4 s) and Bullet wants its own fixed internal step
/// with interpolated poses; its default collision margin (4 cm) is as large as the bodies of a
/// tank test; its sleeping freezes bodies the fluid should still move; it works in single
/// precision (the double build is not what Debian ships) while the kernel's pose is double;
/// and its contact caches (warm-started persistent manifolds) are internal state a checkpoint
/// cannot restore bit for bit. The contacts needed here — boxes, cylinders, spheres and meshes
/// against walls, half-spaces, fixed obstacles and each other — are served by probe points of
/// one shape against the exact signed distance of the other, both ways round.
///
/// Contact force per probe that penetrates δ > 0 along the other shape's outward normal n:
/// the linear spring–dashpot of Cundall & Strack 1979 ("A discrete numerical model for
/// granular assemblies", Géotechnique 29, eqs. 4–6 and the slip condition eq. 7):
///   F_n = max(0, k δ − c v_n),   F_t = −k_t ξ − c v_t,  |F_t| ≤ μ F_n,
/// v the probe's velocity relative to the other shape, ξ the tangential spring stretched by
/// the sliding since the contact began (kept in the tangent plane, reset to the cap when it
/// slips; k_t = k/2). The spring makes static friction hold a body on a slope without creep;
/// its ξ per touching probe is state, saved with the bodies. The stiffness k per probe defaults to
/// k = m g / (N_face · 1e-3 · size): a body resting on a face (N_face probes) sinks 0.1 % of its
/// size; c = 2ζ √(k m / N_face) makes that face critically damped at ζ = 1. At rest the springs
/// carry exactly the weight. The sub-step keeps ω τ ≤ 0.3 for ω² = 2 N_face k / m, and the face's damping
/// rate 2 ζ ω τ ≤ 0.6 (ω² = N_face k / m) for an overdamped contact (ζ > 1.4).

#include <tide/bodies.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>
#include <string>

#include "bodies/checks.hpp"
#include "bodies/contact_shapes.hpp"

namespace tide::bodies {

namespace {

struct ContactParams {
    double stiffness = 0.0;  // per probe, N/m
    double damping = 0.0;    // per probe, N s/m
    double friction = 0.0;
    int probesPerFace = 1;
    double dampingRatio = 1.0;
    double distance = 0.0;  // the gap at which surfaces touch, m
};

struct Contacting {
    glm::dvec3 x{0.0};       // centre of mass (or 0 for fixed)
    glm::dmat3 R{1.0};
    glm::dvec3 c0{0.0};      // rest centre of mass
    glm::dvec3 v{0.0}, w{0.0};
    bool fixed = true;

    [[nodiscard]] glm::dvec3 toWorld(const glm::dvec3& p0) const { return fixed ? p0 : x + R * (p0 - c0); }
    [[nodiscard]] glm::dvec3 toRest(const glm::dvec3& p) const { return fixed ? p : c0 + glm::transpose(R) * (p - x); }
    [[nodiscard]] glm::dvec3 normalToWorld(const glm::dvec3& n0) const { return fixed ? n0 : R * n0; }
    [[nodiscard]] glm::dvec3 velocityAt(const glm::dvec3& p) const {
        return fixed ? glm::dvec3(0.0) : v + glm::cross(w, p - x);
    }
};

Contacting pose(const RigidBody& b) {
    Contacting c;
    c.x = b.position();
    c.R = b.rotation();
    c.c0 = b.massProperties().centerOfMass;
    c.v = b.velocity();
    c.w = b.angularVelocity();
    c.fixed = false;
    return c;
}

struct Load {
    glm::dvec3 force{0.0}, moment{0.0};
};

// A touching probe: (the probing shape, the probed shape, the probe's index). Shapes are
// bodies by index, fixed shapes by kFixed | index.
using ContactKey = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
constexpr std::uint32_t kFixed = 0x80000000u;
using Springs = std::map<ContactKey, glm::dvec3>;

// Tangential springs: read from `current`; when `tau` > 0, stretched by v_t τ and written
// with every probe still touching to `next` (probes that let go are forgotten).
struct Friction {
    const Springs* current = nullptr;
    Springs* next = nullptr;
    double tau = 0.0;
};

}  // namespace

struct BodySystem::Impl {
    glm::dvec3 gravity{0.0};
    std::vector<std::unique_ptr<RigidBody>> bodies;
    std::vector<ContactShape> bodyShapes;
    std::vector<ContactParams> params;
    std::vector<ContactShape> fixedShapes;
    std::vector<std::string> fixedNames;
    bool walls = false;
    glm::dvec3 wallMin{0.0}, wallMax{0.0};
    int obstacleCount = 0;

    // Probes of shape `a` (pose pa) against the signed distance of `b` (pose pb); the force on
    // a's probes goes to loadA (if not null), its reaction to loadB (if not null).
    static void probe(const ContactShape& a, const Contacting& pa, const ContactShape& b, const Contacting& pb,
                      double k, double c, double mu, double gap, Load* loadA, Load* loadB, std::uint32_t idA,
                      std::uint32_t idB, const Friction& friction) {
        for (std::size_t ip = 0; ip < a.probes.size(); ++ip) {
            const ContactProbe& pr = a.probes[ip];
            const glm::dvec3 p = pa.toWorld(pr.point);
            glm::dvec3 n0;
            const double d = signedDistance(b.shape, pb.toRest(p), n0) - pr.radius - gap;
            if (!(d < 0.0)) continue;
            const glm::dvec3 n = pb.normalToWorld(n0);
            const glm::dvec3 at = p - pr.radius * n;  // on a sphere probe's surface
            const glm::dvec3 vrel = pa.velocityAt(at) - pb.velocityAt(at);
            const double vn = glm::dot(vrel, n);
            const double fn = std::max(0.0, -k * d - c * vn);
            if (fn == 0.0) continue;
            const glm::dvec3 vt = vrel - vn * n;
            const ContactKey key{idA, idB, static_cast<std::uint32_t>(ip)};
            glm::dvec3 xi(0.0);
            if (const auto it = friction.current->find(key); it != friction.current->end()) xi = it->second;
            if (friction.tau > 0.0) xi += friction.tau * vt;
            // Into the current tangent plane, keeping its length (the contact frame turns).
            const double len = glm::length(xi);
            xi -= glm::dot(xi, n) * n;
            const double inPlane = glm::length(xi);
            if (inPlane > 0.0) xi *= len / inPlane;
            const double kt = 0.5 * k;
            glm::dvec3 ft = -kt * xi - c * vt;
            const double cap = mu * fn, ftLen = glm::length(ft);
            if (ftLen > cap) {  // slipping: Coulomb's cap, the spring holding what it can (eq. 7)
                ft *= cap / ftLen;
                xi = -(ft + c * vt) / kt;
                if (glm::length(xi) * kt > cap) xi *= cap / (glm::length(xi) * kt);
            }
            if (friction.tau > 0.0) (*friction.next)[key] = xi;
            const glm::dvec3 f = fn * n + ft;
            if (loadA) {
                loadA->force += f;
                loadA->moment += glm::cross(at - pa.x, f);
            }
            if (loadB) {
                loadB->force -= f;
                loadB->moment -= glm::cross(at - pb.x, f);
            }
        }
    }

    Springs springs;  // tangential springs of the touching probes

    // Contact loads at the current state; `tau` > 0 also advances the tangential springs by
    // a sub-step of that length (once per sub-step, at its end).
    void contactLoads(std::vector<Load>& loads, double tau) {
        Springs next;
        const Friction friction{&springs, &next, tau};
        const std::size_t n = bodies.size();
        std::vector<Contacting> poses(n);
        for (std::size_t i = 0; i < n; ++i) poses[i] = pose(*bodies[i]);
        const Contacting still;
        for (std::size_t i = 0; i < n; ++i) {
            if (!bodies[i]->def().contact.enabled) continue;
            const ContactShape& si = bodyShapes[i];
            const ContactParams& pi = params[i];
            const glm::dvec3 ci = poses[i].toWorld(si.center);
            const auto bi = static_cast<std::uint32_t>(i);
            for (std::size_t fi = 0; fi < fixedShapes.size(); ++fi) {
                const ContactShape& f = fixedShapes[fi];
                const auto fid = kFixed | static_cast<std::uint32_t>(fi);
                const bool plane = f.shape.shape == ObstacleDef::Shape::Plane;
                if (plane ? glm::dot(ci - f.center, glm::normalize(glm::dvec3(f.shape.normal))) > si.boundingRadius + pi.distance
                          : glm::length(ci - f.center) > si.boundingRadius + f.boundingRadius + pi.distance)
                    continue;
                probe(si, poses[i], f, still, pi.stiffness, pi.damping, pi.friction, pi.distance, &loads[i], nullptr,
                      bi, fid, friction);
                if (!plane)
                    probe(f, still, si, poses[i], pi.stiffness, pi.damping, pi.friction, pi.distance, nullptr,
                          &loads[i], fid, bi, friction);
            }
            for (std::size_t j = i + 1; j < n; ++j) {
                if (!bodies[j]->def().contact.enabled) continue;
                const ContactShape& sj = bodyShapes[j];
                const ContactParams& pj = params[j];
                const double gap = std::max(pi.distance, pj.distance);
                if (glm::length(ci - poses[j].toWorld(sj.center)) > si.boundingRadius + sj.boundingRadius + gap) continue;
                const double k = pi.stiffness * pj.stiffness / (pi.stiffness + pj.stiffness);
                const double mi = bodies[i]->massProperties().mass, mj = bodies[j]->massProperties().mass;
                const double zeta = 0.5 * (pi.dampingRatio + pj.dampingRatio);
                const double c = 2.0 * zeta * std::sqrt(k * (mi * mj / (mi + mj)) / std::min(pi.probesPerFace, pj.probesPerFace));
                const double mu = std::sqrt(pi.friction * pj.friction);
                const auto bj = static_cast<std::uint32_t>(j);
                probe(si, poses[i], sj, poses[j], k, c, mu, gap, &loads[i], &loads[j], bi, bj, friction);
                probe(sj, poses[j], si, poses[i], k, c, mu, gap, &loads[j], &loads[i], bj, bi, friction);
            }
        }
        if (tau > 0.0) springs = std::move(next);
    }
};

BodySystem::BodySystem(const glm::dvec3& gravity) : impl_(std::make_unique<Impl>()) {
    requireFiniteD("gravity", gravity);
    impl_->gravity = gravity;
}
BodySystem::~BodySystem() = default;
BodySystem::BodySystem(BodySystem&&) noexcept = default;
BodySystem& BodySystem::operator=(BodySystem&&) noexcept = default;

void BodySystem::setWalls(const glm::dvec3& min, const glm::dvec3& max) {
    requireFiniteD("walls.min", min);
    requireFiniteD("walls.max", max);
    if (!(max.x > min.x && max.y > min.y && max.z > min.z))
        throw std::invalid_argument("walls.max: must exceed walls.min on every axis, got " + showd(max));
    for (int k = 0; k < 3; ++k)
        for (int side = 0; side < 2; ++side) {
            ObstacleDef plane;
            plane.shape = ObstacleDef::Shape::Plane;
            plane.point = glm::vec3(side == 0 ? min : max);
            plane.normal = glm::vec3(0.0f);
            plane.normal[k] = side == 0 ? 1.0f : -1.0f;  // the wall's solid lies outside the box
            impl_->fixedShapes.push_back(makeContactShape(plane));
            impl_->fixedNames.push_back(std::string("the wall ") + "xyz"[k] + (side == 0 ? " = min" : " = max"));
        }
    impl_->walls = true;
    impl_->wallMin = min;
    impl_->wallMax = max;
}

void BodySystem::addFixedObstacle(const ObstacleDef& obstacle, const std::string& name) {
    if (obstacle.shape == ObstacleDef::Shape::Plane && !(glm::length(obstacle.normal) > 0.0f))
        throw std::invalid_argument("obstacle.normal: must be non-zero");
    if (obstacle.shape == ObstacleDef::Shape::Mesh && !obstacle.mesh)
        throw std::invalid_argument("obstacle.mesh: no mesh given");
    impl_->fixedShapes.push_back(makeContactShape(obstacle));
    impl_->fixedNames.push_back(name.empty() ? "obstacle" + std::to_string(impl_->obstacleCount) : name);
    ++impl_->obstacleCount;
}

void BodySystem::validatePlacement(double tolerance) const {
    const Impl& m = *impl_;
    const Contacting still;
    // The deepest probe of `a` inside `b`, m (negative inside).
    auto deepest = [](const ContactShape& a, const Contacting& pa, const ContactShape& b, const Contacting& pb,
                      glm::dvec3& where) {
        double worst = std::numeric_limits<double>::infinity();
        for (const ContactProbe& pr : a.probes) {
            const glm::dvec3 p = pa.toWorld(pr.point);
            glm::dvec3 n;
            const double d = signedDistance(b.shape, pb.toRest(p), n) - pr.radius;
            if (d < worst) {
                worst = d;
                where = p;
            }
        }
        return worst;
    };
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
        const RigidBody& bi = *m.bodies[i];
        const Contacting pi = pose(bi);
        glm::dvec3 where;
        for (std::size_t f = 0; f < m.fixedShapes.size(); ++f) {
            double d = deepest(m.bodyShapes[i], pi, m.fixedShapes[f], still, where);
            if (m.fixedShapes[f].shape.shape != ObstacleDef::Shape::Plane)
                d = std::min(d, deepest(m.fixedShapes[f], still, m.bodyShapes[i], pi, where));
            if (d < -tolerance)
                throw std::invalid_argument(bi.def().name + ": overlaps " + m.fixedNames[f] + " by " + showd(-d) +
                                            " m (at " + showd(where) + ")");
        }
        for (std::size_t j = i + 1; j < m.bodies.size(); ++j) {
            const Contacting pj = pose(*m.bodies[j]);
            const double d = std::min(deepest(m.bodyShapes[i], pi, m.bodyShapes[j], pj, where),
                                      deepest(m.bodyShapes[j], pj, m.bodyShapes[i], pi, where));
            if (d < -tolerance)
                throw std::invalid_argument(bi.def().name + ": overlaps " + m.bodies[j]->def().name + " by " +
                                            showd(-d) + " m (at " + showd(where) + ")");
        }
        if (!m.walls) continue;
        for (std::size_t k = 0; k < bi.def().moorings.size(); ++k) {
            const glm::dvec3 a = bi.def().moorings[k].anchor;
            const glm::dvec3 lo = m.wallMin - glm::dvec3(tolerance), hi = m.wallMax + glm::dvec3(tolerance);
            if (a.x < lo.x || a.y < lo.y || a.z < lo.z || a.x > hi.x || a.y > hi.y || a.z > hi.z)
                throw std::invalid_argument(bi.def().name + ".moorings[" + std::to_string(k) +
                                            "].anchor: outside the domain, got " + showd(a));
        }
    }
}

std::size_t BodySystem::addBody(const BodyDef& def) {
    auto body = std::make_unique<RigidBody>(def, impl_->gravity);
    ContactShape shape = makeContactShape(def.shape);
    const ContactDef& cd = def.contact;
    requireNonNegativeD(def.name + ".contact.stiffness", cd.stiffness);
    requirePositiveD(def.name + ".contact.damping_ratio", cd.dampingRatio);
    requireNonNegativeD(def.name + ".contact.friction", cd.friction);
    requireNonNegativeD(def.name + ".contact.distance", cd.distance);
    ContactParams p;
    p.probesPerFace = shape.probesPerFace;
    p.dampingRatio = cd.dampingRatio;
    p.friction = cd.friction;
    p.distance = cd.distance;
    const double m = body->massProperties().mass;
    const double g = glm::length(impl_->gravity) > 0.0 ? glm::length(impl_->gravity) : 9.81;
    p.stiffness = cd.stiffness > 0.0 ? cd.stiffness : m * g / (p.probesPerFace * 1e-3 * body->characteristicSize_);
    p.damping = 2.0 * cd.dampingRatio * std::sqrt(p.stiffness * m / p.probesPerFace);
    impl_->bodies.push_back(std::move(body));
    impl_->bodyShapes.push_back(std::move(shape));
    impl_->params.push_back(p);
    return impl_->bodies.size() - 1;
}

std::size_t BodySystem::size() const { return impl_->bodies.size(); }
RigidBody& BodySystem::body(std::size_t i) { return *impl_->bodies.at(i); }
const RigidBody& BodySystem::body(std::size_t i) const { return *impl_->bodies.at(i); }

void BodySystem::step(double dt, std::span<const glm::dvec3> forces, std::span<const glm::dvec3> moments) {
    const std::size_t n = impl_->bodies.size();
    if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("bodies: step dt must be > 0, got " + showd(dt));
    if ((!forces.empty() && forces.size() != n) || (!moments.empty() && moments.size() != n))
        throw std::invalid_argument("bodies: step needs one force and one moment per body (" + std::to_string(n) + ")");
    if (n == 0) return;
    double tau0 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
        const RigidBody& b = *impl_->bodies[i];
        tau0 = std::min(tau0, b.stableSubstep());
        if (b.def().contact.enabled) {
            const ContactParams& p = impl_->params[i];
            const double omega = std::sqrt(p.probesPerFace * p.stiffness / b.massProperties().mass);  // a face's
            tau0 = std::min(tau0, 0.3 / (std::sqrt(2.0) * omega));
            // The face's damping explicit: its rate 2 ζ ω times τ kept ≤ 0.6 (binds above ζ = 1.4).
            tau0 = std::min(tau0, 0.3 / (p.dampingRatio * omega));
        }
    }
    const int steps = std::max(1, static_cast<int>(std::ceil(dt / tau0)));
    const double tau = dt / steps;

    std::vector<glm::dvec3> v0(n), w0(n), contact(n, glm::dvec3(0.0));
    for (std::size_t i = 0; i < n; ++i) {
        v0[i] = impl_->bodies[i]->velocity();
        w0[i] = impl_->bodies[i]->angularVelocity();
    }
    std::vector<Load> loads(n);
    auto kickAll = [&](double springTau) {
        std::fill(loads.begin(), loads.end(), Load{});
        impl_->contactLoads(loads, springTau);
        for (std::size_t i = 0; i < n; ++i) {
            RigidBody& b = *impl_->bodies[i];
            contact[i] += loads[i].force;
            RigidBody::Loads l = b.internalLoads(false);
            l.force += loads[i].force;
            l.moment += loads[i].moment;
            if (!forces.empty()) l.force += forces[i];
            if (!moments.empty()) l.moment += moments[i];
            b.kick(0.5 * tau, l);
        }
    };
    for (int s = 0; s < steps; ++s) {
        kickAll(0.0);
        for (auto& b : impl_->bodies) b->drift(tau);
        kickAll(tau);  // the sub-step's end: the tangential springs stretch by v_t τ
    }
    for (std::size_t i = 0; i < n; ++i) {
        RigidBody& b = *impl_->bodies[i];
        b.a_ = (b.v_ - v0[i]) / dt;
        b.alpha_ = (b.omega_ - w0[i]) / dt;
        b.contactForce_ = contact[i] / (2.0 * steps);
        b.requireFinite();
        static_cast<void>(b.internalLoads(true));
    }
}

// Layout: the body count, each body's RigidBody::saveState(), the count of touching probes,
// then per probe its key (three integers, exact in double) and its tangential spring ξ.
std::vector<double> BodySystem::saveState() const {
    std::vector<double> s{static_cast<double>(impl_->bodies.size())};
    for (const auto& b : impl_->bodies) {
        const std::vector<double> one = b->saveState();
        s.insert(s.end(), one.begin(), one.end());
    }
    s.push_back(static_cast<double>(impl_->springs.size()));
    for (const auto& [key, xi] : impl_->springs)
        s.insert(s.end(), {static_cast<double>(std::get<0>(key)), static_cast<double>(std::get<1>(key)),
                           static_cast<double>(std::get<2>(key)), xi.x, xi.y, xi.z});
    return s;
}

void BodySystem::restoreState(std::span<const double> s) {
    const std::size_t n = impl_->bodies.size();
    const std::size_t bodiesEnd = 1 + n * RigidBody::kStateSize;
    auto refuse = [&]() {
        return std::invalid_argument("bodies: the saved state is for " + (s.empty() ? std::string("no") : showd(s[0])) +
                                     " bodies or is damaged, this system has " + std::to_string(n));
    };
    if (s.size() < bodiesEnd + 1 || s[0] != static_cast<double>(n)) throw refuse();
    const double count = s[bodiesEnd];
    if (!(count >= 0.0) || s.size() != bodiesEnd + 1 + 6 * static_cast<std::size_t>(count)) throw refuse();
    Springs springs;
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
        const double* e = s.data() + bodiesEnd + 1 + 6 * k;
        const ContactKey key{static_cast<std::uint32_t>(e[0]), static_cast<std::uint32_t>(e[1]),
                             static_cast<std::uint32_t>(e[2])};
        springs[key] = glm::dvec3(e[3], e[4], e[5]);
    }
    for (std::size_t i = 0; i < n; ++i)
        impl_->bodies[i]->restoreState(s.subspan(1 + i * RigidBody::kStateSize, RigidBody::kStateSize));
    impl_->springs = std::move(springs);
}

}  // namespace tide::bodies
