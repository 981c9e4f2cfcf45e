/// \file
/// Exact mass properties of the obstacle shapes. Boxes, spheres and cylinders from their
/// closed forms; closed triangle meshes by the divergence theorem, which turns the volume
/// integrals of 1, x, y, z, x², y², z², xy, yz, zx into sums over the triangles (Eberly 2002,
/// "Polyhedral mass properties (revisited)", Geometric Tools; the same integrals as Mirtich
/// 1996, "Fast and accurate computation of polyhedral mass properties", J. Graphics Tools 1(2)).
/// Nothing here samples particles: identical shapes get identical inertia.

#include <tide/bodies.hpp>
#include <tide/triangle_mesh.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "bodies/checks.hpp"

namespace tide::bodies {

namespace {

glm::dmat3 outer(const glm::dvec3& a, const glm::dvec3& b) {
    // glm is column-major: m[col][row]
    glm::dmat3 m(0.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = a[r] * b[c];
    return m;
}

MassProperties finish(double mass, double volume, const glm::dvec3& com, const glm::dmat3& inertia) {
    MassProperties p;
    p.mass = mass;
    p.volume = volume;
    p.centerOfMass = com;
    p.inertia = inertia;
    computePrincipalAxes(p);
    return p;
}

}  // namespace

void computePrincipalAxes(MassProperties& props) {
    // Cyclic Jacobi rotations (Golub & Van Loan §8.5): a 3×3 symmetric matrix converges to
    // diagonal in a handful of sweeps, in double to round-off.
    double a[3][3];
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = 0.5 * (props.inertia[c][r] + props.inertia[r][c]);
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-32 * diag || off == 0.0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0);
                const double s = t * c;
                for (int k = 0; k < 3; ++k) {  // A ← A J (columns p, q)
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {  // A ← Jᵀ A (rows p, q)
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {  // V ← V J
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (a[order[j]][order[j]] < a[order[i]][order[i]]) std::swap(order[i], order[j]);
    glm::dmat3 axes(0.0);
    for (int i = 0; i < 3; ++i) {
        props.principalMoments[i] = a[order[i]][order[i]];
        for (int k = 0; k < 3; ++k) axes[i][k] = v[k][order[i]];
    }
    if (glm::determinant(axes) < 0.0) axes[2] = -axes[2];
    props.principalAxes = axes;
}

MassProperties boxMassProperties(const glm::dvec3& min, const glm::dvec3& max, double density) {
    const glm::dvec3 size = max - min;
    if (!(size.x > 0.0 && size.y > 0.0 && size.z > 0.0))
        throw std::invalid_argument("box: max must exceed min on every axis, got size " + showd(size));
    const double volume = size.x * size.y * size.z;
    const double m = density * volume;
    glm::dmat3 inertia(0.0);
    inertia[0][0] = m / 12.0 * (size.y * size.y + size.z * size.z);
    inertia[1][1] = m / 12.0 * (size.x * size.x + size.z * size.z);
    inertia[2][2] = m / 12.0 * (size.x * size.x + size.y * size.y);
    return finish(m, volume, 0.5 * (min + max), inertia);
}

MassProperties sphereMassProperties(const glm::dvec3& center, double radius, double density) {
    if (!(radius > 0.0)) throw std::invalid_argument("sphere.radius: must be > 0, got " + showd(radius));
    const double volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
    const double m = density * volume;
    return finish(m, volume, center, glm::dmat3(0.4 * m * radius * radius));
}

MassProperties cylinderMassProperties(const glm::dvec3& center, const glm::dvec3& axis, double radius,
                                      double length, double density) {
    if (!(radius > 0.0)) throw std::invalid_argument("cylinder.radius: must be > 0, got " + showd(radius));
    if (!(length > 0.0)) throw std::invalid_argument("cylinder.length: must be > 0, got " + showd(length));
    if (!(glm::length(axis) > 0.0)) throw std::invalid_argument("cylinder.axis: must be non-zero, got " + showd(axis));
    const glm::dvec3 a = glm::normalize(axis);
    const double volume = M_PI * radius * radius * length;
    const double m = density * volume;
    const double axial = 0.5 * m * radius * radius;
    const double across = m * (3.0 * radius * radius + length * length) / 12.0;
    const glm::dmat3 aa = outer(a, a);
    return finish(m, volume, center, axial * aa + across * (glm::dmat3(1.0) - aa));
}

MassProperties meshMassProperties(const TriangleMesh& mesh, double density) {
    // Integrate about a point inside the bounds: the parallel-axis shift back to the centre of
    // mass then cancels little (a mesh far from the origin keeps its digits).
    const glm::dvec3 ref = 0.5 * (glm::dvec3(mesh.boundsMin()) + glm::dvec3(mesh.boundsMax()));
    double intg[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    const auto& verts = mesh.vertices();
    auto sub = [](double w0, double w1, double w2, double& f1, double& f2, double& f3, double& g0, double& g1,
                  double& g2) {
        const double t0 = w0 + w1;
        f1 = t0 + w2;
        const double t1 = w0 * w0;
        const double t2 = t1 + w1 * t0;
        f2 = t2 + w2 * f1;
        f3 = w0 * t1 + w1 * t2 + w2 * f2;
        g0 = f2 + w0 * (f1 + w0);
        g1 = f2 + w1 * (f1 + w1);
        g2 = f2 + w2 * (f1 + w2);
    };
    for (const auto& tri : mesh.triangles()) {
        const glm::dvec3 p0 = glm::dvec3(verts[tri.x]) - ref;
        const glm::dvec3 p1 = glm::dvec3(verts[tri.y]) - ref;
        const glm::dvec3 p2 = glm::dvec3(verts[tri.z]) - ref;
        const glm::dvec3 d = glm::cross(p1 - p0, p2 - p0);  // counter-clockwise from outside: outward
        double f1x, f2x, f3x, g0x, g1x, g2x, f1y, f2y, f3y, g0y, g1y, g2y, f1z, f2z, f3z, g0z, g1z, g2z;
        sub(p0.x, p1.x, p2.x, f1x, f2x, f3x, g0x, g1x, g2x);
        sub(p0.y, p1.y, p2.y, f1y, f2y, f3y, g0y, g1y, g2y);
        sub(p0.z, p1.z, p2.z, f1z, f2z, f3z, g0z, g1z, g2z);
        intg[0] += d.x * f1x;
        intg[1] += d.x * f2x;
        intg[2] += d.y * f2y;
        intg[3] += d.z * f2z;
        intg[4] += d.x * f3x;
        intg[5] += d.y * f3y;
        intg[6] += d.z * f3z;
        intg[7] += d.x * (p0.y * g0x + p1.y * g1x + p2.y * g2x);
        intg[8] += d.y * (p0.z * g0y + p1.z * g1y + p2.z * g2y);
        intg[9] += d.z * (p0.x * g0z + p1.x * g1z + p2.x * g2z);
    }
    const double mult[10] = {1.0 / 6, 1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 60,
                             1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
    for (int i = 0; i < 10; ++i) intg[i] *= mult[i];
    const double volume = intg[0];
    if (!(volume > 0.0)) throw std::invalid_argument("mesh: encloses no volume (got " + showd(volume) + " m^3)");
    const glm::dvec3 c(intg[1] / volume, intg[2] / volume, intg[3] / volume);
    // Second moments about c per unit density (Eberly 2002, "Polyhedral mass properties").
    glm::dmat3 inertia(0.0);
    inertia[0][0] = intg[5] + intg[6] - volume * (c.y * c.y + c.z * c.z);
    inertia[1][1] = intg[4] + intg[6] - volume * (c.z * c.z + c.x * c.x);
    inertia[2][2] = intg[4] + intg[5] - volume * (c.x * c.x + c.y * c.y);
    inertia[1][0] = inertia[0][1] = -(intg[7] - volume * c.x * c.y);
    inertia[2][1] = inertia[1][2] = -(intg[8] - volume * c.y * c.z);
    inertia[2][0] = inertia[0][2] = -(intg[9] - volume * c.z * c.x);
    return finish(density * volume, volume, c + ref, density * inertia);
}

MassProperties obstacleMassProperties(const ObstacleDef& shape, double density, const std::string& path) {
    requirePositiveD(path + ".density", density);
    try {
        switch (shape.shape) {
            case ObstacleDef::Shape::Box:
                return boxMassProperties(glm::dvec3(shape.min), glm::dvec3(shape.max), density);
            case ObstacleDef::Shape::Sphere:
                return sphereMassProperties(glm::dvec3(shape.center), shape.radius, density);
            case ObstacleDef::Shape::Cylinder:
                return cylinderMassProperties(glm::dvec3(shape.center), glm::dvec3(shape.axis), shape.radius,
                                              shape.length, density);
            case ObstacleDef::Shape::Mesh:
                if (!shape.mesh) throw std::invalid_argument("mesh: no mesh given");
                return meshMassProperties(*shape.mesh, density);
            case ObstacleDef::Shape::Plane:
                throw std::invalid_argument("shape: a plane has no mass (use a box, sphere, cylinder or mesh)");
            case ObstacleDef::Shape::Circle:
            case ObstacleDef::Shape::Polygon:
                throw std::invalid_argument("shape: floating bodies are 3D only (a circle or polygon cannot be one)");
        }
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(path + "." + e.what());
    }
    throw std::invalid_argument(path + ".shape: unknown shape");
}

}  // namespace tide::bodies
