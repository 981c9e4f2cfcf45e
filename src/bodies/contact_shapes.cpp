/// \file
/// Contact geometry of the obstacle shapes, in double. Probes: a box's surface lattice (its
/// corners, points along its edges and inside its faces — corner probes alone miss two
/// equal boxes stacked exactly, whose corners lie on each other's side faces); a cylinder's
/// two rims, cap rings and side lines; a mesh's vertices; a sphere's centre with its radius.

#include "bodies/contact_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include <tide/triangle_mesh.hpp>

namespace tide::bodies {

namespace {

glm::dvec3 anyPerpendicular(const glm::dvec3& a) {
    const glm::dvec3 t = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(a, t));
}

}  // namespace

ContactShape makeContactShape(const ObstacleDef& shape) {
    ContactShape out;
    out.shape = shape;
    switch (shape.shape) {
        case ObstacleDef::Shape::Box: {
            const glm::dvec3 lo(shape.min), hi(shape.max), size = hi - lo;
            const double smallest = std::min({size.x, size.y, size.z});
            int n[3];
            for (int k = 0; k < 3; ++k)  // probes no farther apart than a third of the smallest side
                n[k] = std::clamp(static_cast<int>(std::ceil(3.0 * size[k] / smallest - 1e-9)) + 1, 4, 16);
            for (int i = 0; i < n[0]; ++i)
                for (int j = 0; j < n[1]; ++j)
                    for (int k = 0; k < n[2]; ++k) {
                        const bool surface = i == 0 || j == 0 || k == 0 || i == n[0] - 1 || j == n[1] - 1 || k == n[2] - 1;
                        if (!surface) continue;
                        const glm::dvec3 f(double(i) / (n[0] - 1), double(j) / (n[1] - 1), double(k) / (n[2] - 1));
                        out.probes.push_back({lo + f * size, 0.0});
                    }
            out.probesPerFace = std::max({n[0] * n[1], n[1] * n[2], n[0] * n[2]});
            out.center = 0.5 * (lo + hi);
            break;
        }
        case ObstacleDef::Shape::Sphere:
            out.center = glm::dvec3(shape.center);
            out.probes.push_back({out.center, double(shape.radius)});
            out.probesPerFace = 1;
            break;
        case ObstacleDef::Shape::Cylinder: {
            const glm::dvec3 c(shape.center), a = glm::normalize(glm::dvec3(shape.axis));
            const glm::dvec3 e1 = anyPerpendicular(a), e2 = glm::cross(a, e1);
            const double r = shape.radius, half = 0.5 * double(shape.length);
            constexpr int kAround = 16;
            for (int cap = -1; cap <= 1; cap += 2) {
                const glm::dvec3 cc = c + double(cap) * half * a;
                out.probes.push_back({cc, 0.0});
                for (int i = 0; i < kAround; ++i) {
                    const double phi = 2.0 * M_PI * i / kAround;
                    const glm::dvec3 radial = std::cos(phi) * e1 + std::sin(phi) * e2;
                    out.probes.push_back({cc + r * radial, 0.0});
                    if (i % 2 == 0) out.probes.push_back({cc + 0.5 * r * radial, 0.0});
                }
            }
            const int along = std::clamp(static_cast<int>(std::ceil(2.0 * half / (0.5 * r))), 2, 16);
            for (int j = 1; j < along; ++j)
                for (int i = 0; i < kAround; ++i) {
                    const double phi = 2.0 * M_PI * i / kAround;
                    const double t = -half + 2.0 * half * j / along;
                    out.probes.push_back({c + t * a + r * (std::cos(phi) * e1 + std::sin(phi) * e2), 0.0});
                }
            out.probesPerFace = 1 + kAround + kAround / 2;
            out.center = c;
            break;
        }
        case ObstacleDef::Shape::Mesh: {
            if (!shape.mesh) throw std::invalid_argument("mesh: no mesh given");
            glm::dvec3 lo(shape.mesh->boundsMin()), hi(shape.mesh->boundsMax());
            out.center = 0.5 * (lo + hi);
            for (const auto& v : shape.mesh->vertices()) out.probes.push_back({glm::dvec3(v), 0.0});
            out.probesPerFace = std::max<int>(1, static_cast<int>(out.probes.size()) / 6);
            break;
        }
        case ObstacleDef::Shape::Plane:
            out.center = glm::dvec3(shape.point);
            out.boundingRadius = std::numeric_limits<double>::infinity();
            return out;
        case ObstacleDef::Shape::Circle:
        case ObstacleDef::Shape::Polygon: break;  // 2D worlds have no bodies
    }
    for (const auto& p : out.probes)
        out.boundingRadius = std::max(out.boundingRadius, glm::length(p.point - out.center) + p.radius);
    return out;
}

double signedDistance(const ObstacleDef& shape, const glm::dvec3& p, glm::dvec3& normal) {
    switch (shape.shape) {
        case ObstacleDef::Shape::Box: {
            const glm::dvec3 lo(shape.min), hi(shape.max);
            const glm::dvec3 c = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
            const glm::dvec3 d = p - c;
            const glm::dvec3 q = glm::abs(d) - half;
            const glm::dvec3 outside = glm::max(q, glm::dvec3(0.0));
            const double out = glm::length(outside);
            if (out > 0.0) {
                normal = glm::dvec3(std::copysign(outside.x, d.x), std::copysign(outside.y, d.y),
                                    std::copysign(outside.z, d.z)) / out;
                return out;
            }
            int k = 0;
            if (q.y > q[k]) k = 1;
            if (q.z > q[k]) k = 2;
            normal = glm::dvec3(0.0);
            normal[k] = d[k] >= 0.0 ? 1.0 : -1.0;
            return q[k];
        }
        case ObstacleDef::Shape::Sphere: {
            const glm::dvec3 d = p - glm::dvec3(shape.center);
            const double r = glm::length(d);
            normal = r > 0.0 ? d / r : glm::dvec3(0.0, 1.0, 0.0);
            return r - double(shape.radius);
        }
        case ObstacleDef::Shape::Cylinder: {
            // A 2D box in (distance from the axis, distance along it).
            const glm::dvec3 a = glm::normalize(glm::dvec3(shape.axis));
            const glm::dvec3 d = p - glm::dvec3(shape.center);
            const double t = glm::dot(d, a);
            const glm::dvec3 radialVec = d - t * a;
            const double rho = glm::length(radialVec);
            const glm::dvec3 er = rho > 0.0 ? radialVec / rho : anyPerpendicular(a);
            const double qr = rho - double(shape.radius), qa = std::abs(t) - 0.5 * double(shape.length);
            const glm::dvec3 ea = t >= 0.0 ? a : -a;
            if (qr > 0.0 || qa > 0.0) {
                const double orr = std::max(qr, 0.0), oa = std::max(qa, 0.0);
                const double dist = std::sqrt(orr * orr + oa * oa);
                normal = (orr * er + oa * ea) / dist;
                return dist;
            }
            normal = qr > qa ? er : ea;
            return std::max(qr, qa);
        }
        case ObstacleDef::Shape::Mesh: {
            glm::vec3 n;
            const double dist = shape.mesh->signedDistance(glm::vec3(p), &n);
            normal = glm::dvec3(n);
            return dist;
        }
        case ObstacleDef::Shape::Plane: {
            normal = glm::normalize(glm::dvec3(shape.normal));
            return glm::dot(p - glm::dvec3(shape.point), normal);
        }
        case ObstacleDef::Shape::Circle:
        case ObstacleDef::Shape::Polygon: break;  // 2D worlds have no bodies
    }
    normal = glm::dvec3(0.0, 1.0, 0.0);
    return std::numeric_limits<double>::infinity();
}

}  // namespace tide::bodies
