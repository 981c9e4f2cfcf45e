// Obstacles: exact signed distances of every shape against analytic values and brute force,
// mesh validation, sampling, and fluid that never ends up inside one.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tide/io/mesh.hpp>
#include <tide/triangle_mesh.hpp>
#include <tide/world.hpp>

#include "boundary/boundary_particles.hpp"
#include "boundary/obstacles.hpp"
#include "core/periodic_box.hpp"

namespace {

using namespace tide;

/// The box [lo, hi] as 12 outward-facing triangles.
TriangleMesh cubeMesh(const glm::vec3& lo, const glm::vec3& hi, bool inward = false) {
    std::vector<glm::vec3> v;
    for (int k = 0; k < 8; ++k) v.emplace_back(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    // Corner k has x = bit 0, y = bit 1, z = bit 2; each face is counter-clockwise from outside.
    std::vector<glm::uvec3> t{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},   // z = lo, z = hi
                              {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},   // y = lo, y = hi
                              {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};  // x = lo, x = hi
    if (inward)
        for (auto& tri : t) std::swap(tri.y, tri.z);
    return TriangleMesh(v, t);
}

/// A UV sphere: `slices` around, `stacks` from pole to pole; 2·slices·(stacks − 1) triangles.
TriangleMesh uvSphere(const glm::vec3& centre, float radius, int slices, int stacks) {
    std::vector<glm::vec3> v{centre + glm::vec3(0, radius, 0), centre - glm::vec3(0, radius, 0)};
    for (int s = 1; s < stacks; ++s)
        for (int k = 0; k < slices; ++k) {
            const float theta = 3.14159265f * static_cast<float>(s) / static_cast<float>(stacks);
            const float phi = 2.0f * 3.14159265f * static_cast<float>(k) / static_cast<float>(slices);
            v.push_back(centre + radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                    std::sin(theta) * std::sin(phi)));
        }
    auto ring = [&](int s, int k) { return static_cast<unsigned>(2 + (s - 1) * slices + (k % slices)); };
    std::vector<glm::uvec3> t;
    for (int k = 0; k < slices; ++k) {
        t.emplace_back(0u, ring(1, k + 1), ring(1, k));
        t.emplace_back(1u, ring(stacks - 1, k), ring(stacks - 1, k + 1));
        for (int s = 1; s + 1 < stacks; ++s) {
            t.emplace_back(ring(s, k), ring(s, k + 1), ring(s + 1, k));
            t.emplace_back(ring(s, k + 1), ring(s + 1, k + 1), ring(s + 1, k));
        }
    }
    return TriangleMesh(v, t);
}

ObstacleDef boxObstacle(const glm::vec3& lo, const glm::vec3& hi) {
    ObstacleDef o;
    o.shape = ObstacleDef::Shape::Box;
    o.min = lo;
    o.max = hi;
    return o;
}

ObstacleDef meshObstacle(std::shared_ptr<const TriangleMesh> mesh) {
    ObstacleDef o;
    o.shape = ObstacleDef::Shape::Mesh;
    o.mesh = std::move(mesh);
    return o;
}

ObstacleDef cylinderObstacle(const glm::vec3& centre, const glm::vec3& axis, float radius, float length) {
    ObstacleDef o;
    o.shape = ObstacleDef::Shape::Cylinder;
    o.center = centre;
    o.axis = glm::normalize(axis);
    o.radius = radius;
    o.length = length;
    return o;
}

ObstacleDef planeObstacle(const glm::vec3& point, const glm::vec3& normal) {
    ObstacleDef o;
    o.shape = ObstacleDef::Shape::Plane;
    o.point = point;
    o.normal = glm::normalize(normal);
    return o;
}

/// Central-difference gradient of the signed distance.
glm::vec3 numericGradient(const ObstacleDef& o, const glm::vec3& x, float step = 1e-3f) {
    glm::vec3 g;
    for (int a = 0; a < 3; ++a) {
        glm::vec3 e(0.0f);
        e[a] = step;
        g[a] = (signedDistance(o, x + e) - signedDistance(o, x - e)) / (2.0f * step);
    }
    return g;
}

TEST(ObstacleDistance, CylinderMatchesItsRegions) {
    // Axis along y through (1, 2, 3): radius 0.5, length 2 (caps at y = 1 and y = 3).
    const ObstacleDef c = cylinderObstacle({1, 2, 3}, {0, 1, 0}, 0.5f, 2.0f);
    glm::vec3 n;
    EXPECT_NEAR(signedDistance(c, {1, 2, 3}, &n), -0.5f, 1e-6f);                 // centre: nearest is the side
    EXPECT_NEAR(signedDistance(c, {1, 2.9f, 3}, &n), -0.1f, 1e-6f);              // near the top cap
    EXPECT_NEAR(glm::distance(n, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(signedDistance(c, {2, 2, 3}, &n), 0.5f, 1e-6f);                  // beside
    EXPECT_NEAR(glm::distance(n, glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(signedDistance(c, {1, 0.25f, 3}, &n), 0.75f, 1e-6f);             // below the bottom cap
    EXPECT_NEAR(glm::distance(n, glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(signedDistance(c, {1, 4, 3 + 1.5f}, &n), std::sqrt(2.0f), 1e-6f);  // beyond the rim
    EXPECT_NEAR(glm::distance(n, glm::normalize(glm::vec3(0, 1, 1))), 0.0f, 1e-6f);

    // A tilted cylinder: compare with the definition at random points, and the normal with
    // the distance's gradient wherever that is smooth.
    const glm::vec3 axis = glm::normalize(glm::vec3(1, 2, -0.5f));
    const ObstacleDef t = cylinderObstacle({0.2f, -0.1f, 0.3f}, axis, 0.3f, 0.8f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 x(u(rng), u(rng), u(rng));
        const glm::vec3 r = x - t.center;
        const double along = glm::dot(r, axis), rho = glm::length(r - static_cast<float>(along) * axis);
        const double qx = rho - 0.3, qy = std::abs(along) - 0.4;
        const double expected = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
        const float d = signedDistance(t, x, &n);
        ASSERT_NEAR(d, expected, 1e-5) << i;
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
        if (std::abs(qx - qy) > 0.01 && rho > 0.01) {
            EXPECT_LT(glm::distance(n, numericGradient(t, x)), 1e-2f) << i;
        }
    }
}

TEST(ObstacleDistance, PlaneIsTheHalfSpaceBehindItsNormal) {
    const ObstacleDef p = planeObstacle({0.5f, 0.2f, 0.0f}, {-1, 2, 0});  // a beach rising along −x
    glm::vec3 n;
    EXPECT_NEAR(signedDistance(p, {0.5f, 0.2f, 7.0f}, &n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(n, glm::normalize(glm::vec3(-1, 2, 0))), 0.0f, 1e-6f);
    EXPECT_NEAR(signedDistance(p, {0.5f, 0.2f + std::sqrt(5.0f), 0.0f}), 2.0f, 1e-5f);
    EXPECT_NEAR(signedDistance(p, {0.5f + std::sqrt(5.0f), 0.2f, 0.0f}), -1.0f, 1e-5f);
}

TEST(ObstacleDistance, CubeMeshMatchesTheBox) {
    const glm::vec3 lo(0.1f, -0.2f, 0.3f), hi(0.6f, 0.4f, 0.5f);
    const ObstacleDef box = boxObstacle(lo, hi);
    for (bool inward : {false, true}) {  // an inside-out mesh is turned outward
        const ObstacleDef mesh = meshObstacle(std::make_shared<const TriangleMesh>(cubeMesh(lo, hi, inward)));
        EXPECT_NEAR(mesh.mesh->volume(), 0.5 * 0.6 * 0.2, 1e-6);
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> u(-1.0f, 1.5f);
        int inside = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 x(u(rng), u(rng), u(rng));
            glm::vec3 nb, nm;
            const float db = signedDistance(box, x, &nb), dm = signedDistance(mesh, x, &nm);
            ASSERT_NEAR(dm, db, 1e-4f) << x.x << " " << x.y << " " << x.z;
            if (db > 1e-2f) {  // outside, the gradient is unique
                EXPECT_LT(glm::distance(nb, nm), 1e-4f) << x.x << " " << x.y << " " << x.z;
            }
            inside += db < 0.0f;
        }
        EXPECT_GT(inside, 50);
    }
}

/// Brute-force oracle: the distance to the nearest of all triangles, signed by ray parity.
float bruteSignedDistance(const TriangleMesh& mesh, const glm::vec3& x) {
    const auto& v = mesh.vertices();
    float best = INFINITY;
    int crossings = 0;
    const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, 0.91f, 0.27f));  // a direction no edge is parallel to
    for (const glm::uvec3& t : mesh.triangles()) {
        const glm::vec3 a = v[t.x], b = v[t.y], c = v[t.z];
        // Distance to the triangle: inside its face region or to its nearest edge.
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
        const glm::vec3 p = x - glm::dot(x - a, normal) * normal;
        const bool inFace = glm::dot(glm::cross(b - a, p - a), normal) >= 0 && glm::dot(glm::cross(c - b, p - b), normal) >= 0 &&
                            glm::dot(glm::cross(a - c, p - c), normal) >= 0;
        float d = inFace ? std::abs(glm::dot(x - a, normal)) : INFINITY;
        for (auto [e0, e1] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
            const float s = std::clamp(glm::dot(x - e0, e1 - e0) / glm::dot(e1 - e0, e1 - e0), 0.0f, 1.0f);
            d = std::min(d, glm::distance(x, e0 + s * (e1 - e0)));
        }
        best = std::min(best, d);
        // Möller–Trumbore ray/triangle intersection.
        const glm::vec3 e1 = b - a, e2 = c - a, h = glm::cross(dir, e2);
        const float det = glm::dot(e1, h);
        if (std::abs(det) < 1e-12f) continue;
        const glm::vec3 s = x - a;
        const float uu = glm::dot(s, h) / det;
        const glm::vec3 q = glm::cross(s, e1);
        const float vv = glm::dot(dir, q) / det;
        if (uu >= 0 && vv >= 0 && uu + vv <= 1 && glm::dot(e2, q) / det > 0) ++crossings;
    }
    return crossings % 2 ? -best : best;
}

TEST(ObstacleDistance, RockMeshAgreesWithBruteForceAndRayParity) {
    // The shipped rock is not convex: this checks the BVH search and the pseudo-normal sign.
    const auto rock = io::loadMesh(std::string(TIDE_SCENES_DIR) + "/models/rock.obj");
    ASSERT_EQ(rock->triangles().size(), 320u);
    const glm::vec3 lo = rock->boundsMin() - 0.05f, hi = rock->boundsMax() + 0.05f;
    std::mt19937 rng(3);
    int inside = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 x(std::uniform_real_distribution<float>(lo.x, hi.x)(rng),
                          std::uniform_real_distribution<float>(lo.y, hi.y)(rng),
                          std::uniform_real_distribution<float>(lo.z, hi.z)(rng));
        const float expected = bruteSignedDistance(*rock, x);
        if (std::abs(expected) < 1e-4f) continue;  // the parity test is unreliable on the surface
        ASSERT_NEAR(rock->signedDistance(x), expected, 1e-5f) << x.x << " " << x.y << " " << x.z;
        inside += expected < 0.0f;
    }
    EXPECT_GT(inside, 300);
    // The flat base lies at y = 0 (the file's own convention).
    EXPECT_NEAR(rock->boundsMin().y, 0.0f, 1e-6f);
}

TEST(ObstacleDistance, SphereMeshConvergesToTheSphere) {
    const TriangleMesh sphere = uvSphere({0, 0, 0}, 1.0f, 64, 32);
    for (const glm::vec3 x : {glm::vec3(0, 0, 0), glm::vec3(0.3f, 0.2f, -0.1f), glm::vec3(2, 1, 0), glm::vec3(0, -3, 0)}) {
        glm::vec3 n;
        const float d = sphere.signedDistance(x, &n);
        EXPECT_NEAR(d, glm::length(x) - 1.0f, 5e-3f);
        if (glm::length(x) > 0.1f) {
            EXPECT_GT(glm::dot(n, glm::normalize(x)), 0.99f);
        }
    }
}

TEST(TriangleMesh, RejectsMeshesThatAreNotClosedSolids) {
    auto expectRejected = [](std::vector<glm::vec3> v, std::vector<glm::uvec3> t, const std::string& why) {
        try {
            TriangleMesh mesh(std::move(v), std::move(t));
            ADD_FAILURE() << "accepted a mesh that " << why;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    };
    const TriangleMesh cube = cubeMesh({0, 0, 0}, {1, 1, 1});
    const auto v = cube.vertices();
    std::vector<glm::uvec3> t(cube.triangles().begin(), cube.triangles().end());

    expectRejected(v, {}, "no triangles");
    auto open = t;
    open.pop_back();
    expectRejected(v, open, "borders only one triangle");
    auto flipped = t;
    std::swap(flipped[3].y, flipped[3].z);
    expectRejected(v, flipped, "facing opposite ways");
    auto outOfRange = t;
    outOfRange[0].x = 99;
    expectRejected(v, outOfRange, "vertex 99");
    auto degenerate = v;
    degenerate.push_back(degenerate[0]);  // merged with vertex 0: a triangle with a repeated corner
    auto withDegenerate = t;
    withDegenerate.emplace_back(0u, 8u, 1u);
    expectRejected(degenerate, withDegenerate, "degenerate");
    auto nan = v;
    nan[2].y = std::nanf("");
    expectRejected(nan, t, "not finite");
    // Two cubes sharing an edge: four triangles meet at it.
    auto two = v;
    auto twoT = t;
    for (const glm::vec3& p : v) two.push_back(p + glm::vec3(1, 1, 0));
    for (const glm::uvec3& tri : t) twoT.push_back(tri + 8u);
    expectRejected(two, twoT, "shared by 4 triangles");
}

TEST(TriangleMesh, SplitVerticesAreMerged) {
    // Every triangle with its own three corners (as STL-like exports do) still closes.
    const TriangleMesh cube = cubeMesh({0, 0, 0}, {1, 1, 1});
    std::vector<glm::vec3> v;
    std::vector<glm::uvec3> t;
    for (const glm::uvec3& tri : cube.triangles()) {
        const auto n = static_cast<unsigned>(v.size());
        for (int k = 0; k < 3; ++k) v.push_back(cube.vertices()[tri[k]]);
        t.emplace_back(n, n + 1, n + 2);
    }
    const TriangleMesh split(v, t);
    EXPECT_EQ(split.vertices().size(), 8u);
    EXPECT_NEAR(split.signedDistance({0.5f, 0.5f, 2.0f}), 1.0f, 1e-6f);
}

/// Every sampled point lies in the band −depth < d ≤ kOnSurface·spacing (on the surface, to
/// rounding) and inside the clip box, and every lattice point of that band is sampled.
void expectBandSampled(const ObstacleDef& o, float spacing, float depth, const glm::vec3& clipMin, const glm::vec3& clipMax) {
    const glm::vec3 origin(0.0f);
    const auto points = sampleObstacle(o, origin, spacing, depth, clipMin, clipMax, 2);
    ASSERT_FALSE(points.empty());
    for (const glm::vec3& x : points) {
        const float d = signedDistance(o, x);
        ASSERT_LE(d, kOnSurface * spacing);
        ASSERT_GT(d, -depth);
        ASSERT_TRUE(glm::all(glm::greaterThanEqual(x, clipMin)) && glm::all(glm::lessThanEqual(x, clipMax)));
    }
    std::size_t expected = 0;
    const glm::ivec3 first(glm::floor(clipMin / spacing)), last(glm::ceil(clipMax / spacing));
    for (int k = first.z; k <= last.z; ++k)
        for (int j = first.y; j <= last.y; ++j)
            for (int i = first.x; i <= last.x; ++i) {
                const glm::vec3 x = spacing * (glm::vec3(static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)) + 0.5f);
                if (glm::any(glm::lessThan(x, clipMin)) || glm::any(glm::greaterThan(x, clipMax))) continue;
                const float d = signedDistance(o, x);
                expected += d <= kOnSurface * spacing && d > -depth;
            }
    EXPECT_EQ(points.size(), expected);
    // The same points in the same order on one thread.
    EXPECT_EQ(sampleObstacle(o, origin, spacing, depth, clipMin, clipMax, 1), points);
}

TEST(ObstacleSampling, EveryShapeSamplesItsSurfaceBand) {
    const glm::vec3 clipMin(-0.1f), clipMax(1.1f);
    const float s = 0.02f, depth = 0.04f;
    expectBandSampled(boxObstacle({0.2f, 0.0f, 0.3f}, {0.5f, 0.25f, 0.6f}), s, depth, clipMin, clipMax);
    expectBandSampled(cylinderObstacle({0.5f, 0.5f, 0.5f}, {1, 1, 0}, 0.15f, 0.4f), s, depth, clipMin, clipMax);
    expectBandSampled(cylinderObstacle({0.5f, 0.2f, 0.5f}, {0, 1, 0}, 0.1f, 0.4f), s, depth, clipMin, clipMax);
    // An infinite plane is cut off at the clip box.
    expectBandSampled(planeObstacle({0.0f, 0.3f, 0.0f}, {-0.3f, 1.0f, 0.0f}), s, depth, clipMin, clipMax);
    expectBandSampled(meshObstacle(std::make_shared<const TriangleMesh>(uvSphere({0.5f, 0.5f, 0.5f}, 0.3f, 40, 20))), s,
                      depth, clipMin, clipMax);
}

TEST(ObstacleSampling, TenThousandTriangleMeshSamplesWellUnderASecond) {
    // A sphere of 10 000 triangles, 1 m across, at 0.02 m: ~130 000 lattice points to test.
    const auto sphere = std::make_shared<const TriangleMesh>(uvSphere({0.5f, 0.5f, 0.5f}, 0.5f, 100, 51));
    ASSERT_EQ(sphere->triangles().size(), 10000u);
    // CPU time of this thread, not wall time: other processes on the machine do not count.
    const auto cpuSeconds = [] {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    };
    const double start = cpuSeconds();
    const auto points = sampleObstacle(meshObstacle(sphere), glm::vec3(0.0f), 0.02f, 0.04f, glm::vec3(-1.0f), glm::vec3(2.0f), 1);
    const double seconds = cpuSeconds() - start;
    std::printf("sampled a 10k-triangle mesh at 0.02 m in %.3f s of CPU on one thread: %zu boundary particles\n", seconds,
                points.size());
    // The shell of a ball, radius 0.5 m and 0.04 m deep, holds about its volume / 0.02³.
    const double shell = 4.0 / 3.0 * 3.14159265 * (0.125 - std::pow(0.46, 3)) / (0.02 * 0.02 * 0.02);
    EXPECT_NEAR(static_cast<double>(points.size()), shell, 0.05 * shell);
    EXPECT_LT(seconds, 1.0);
}

TEST(BoundaryParticles, OverlappingSolidsAreSampledOnce) {
    BoundaryParticles b;
    b.sampleBoxShell({0, 0, 0}, {0.2f, 0.2f, 0.2f}, 0.02f, 2, 1.0f, 0.04f, 1);
    const auto shell = b.size();
    // A box obstacle poking through the floor: its points below the floor are shell points.
    const auto points = sampleObstacle(boxObstacle({0.05f, -0.1f, 0.05f}, {0.15f, 0.1f, 0.15f}), glm::vec3(0.0f), 0.02f,
                                       0.04f, glm::vec3(-0.04f), glm::vec3(0.24f), 1);
    std::size_t below = 0;
    for (const glm::vec3& x : points) below += x.y < 0.0f;
    ASSERT_GT(below, 0u);
    EXPECT_EQ(b.add(points, 1.0f, 0.01f, 0.04f, 2), points.size() - below);
    EXPECT_EQ(b.add(points, 1.0f, 0.01f, 0.04f, 2), 0u);  // the same solid again adds nothing
    EXPECT_EQ(b.size(), shell + points.size() - below);
}

// Every boundary particle samples the fluid's lattice, so they share one volume; particles of
// another volume are refused, naming both, and none is added.
TEST(BoundaryParticles, ShareOneVolume) {
    BoundaryParticles b;
    b.sampleBoxShell({0, 0, 0}, {0.2f, 0.2f, 0.2f}, 0.02f, 2, 8e-6f, 0.04f, 1);
    EXPECT_EQ(b.volume, 8e-6f);
    const auto shell = b.size();
    const std::vector<glm::vec3> inside{{0.1f, 0.1f, 0.1f}};
    try {
        b.addMoving(inside, 1e-5f);
        ADD_FAILURE() << "accepted a second volume";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("volume"), std::string::npos) << e.what();
    }
    EXPECT_THROW(b.add(inside, 1e-5f, 0.01f, 0.04f, 1), std::invalid_argument);
    EXPECT_EQ(b.size(), shell);
    EXPECT_EQ(b.add(inside, 8e-6f, 0.01f, 0.04f, 1), 1u);
}

TEST(World, ValidatesAndNormalisesObstacles) {
    WorldDef def;
    def.particleSpacing = 0.05f;
    World world(def);
    auto expectRejected = [&](ObstacleDef o, const std::string& field) {
        try {
            world.addObstacle(o);
            ADD_FAILURE() << "accepted a bad " << field;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    expectRejected(cylinderObstacle({0.5f, 0.5f, 0.5f}, {0, 1, 0}, -0.1f, 0.2f), "obstacle.radius");
    expectRejected(cylinderObstacle({0.5f, 0.5f, 0.5f}, {0, 1, 0}, 0.1f, 0.0f), "obstacle.length");
    ObstacleDef noAxis = cylinderObstacle({0.5f, 0.5f, 0.5f}, {0, 1, 0}, 0.1f, 0.2f);
    noAxis.axis = glm::vec3(0.0f);
    expectRejected(noAxis, "obstacle.axis");
    ObstacleDef noNormal = planeObstacle({0, 0.1f, 0}, {0, 1, 0});
    noNormal.normal = glm::vec3(0.0f);
    expectRejected(noNormal, "obstacle.normal");
    expectRejected(meshObstacle(nullptr), "obstacle.mesh");
    EXPECT_TRUE(world.obstacles().empty());

    ObstacleDef beach = planeObstacle({0, 0.1f, 0}, {0, 1, 0});
    beach.normal = {-1, 2, 0};  // not unit: World normalises it
    world.addObstacle(beach);
    ASSERT_EQ(world.obstacles().size(), 1u);
    EXPECT_NEAR(glm::length(world.obstacles()[0].normal), 1.0f, 1e-6f);
}

TEST(World, BlocksLeaveOutEveryObstacle) {
    WorldDef def;
    def.particleSpacing = 0.05f;
    World world(def);
    world.addMaterial({});
    world.addObstacle(planeObstacle({0, 0.2f, 0}, {-0.5f, 1, 0}));
    world.addObstacle(cylinderObstacle({0.5f, 0.6f, 0.5f}, {0, 0, 1}, 0.15f, 0.6f));
    world.addObstacle(meshObstacle(std::make_shared<const TriangleMesh>(cubeMesh({0.7f, 0.5f, 0.1f}, {0.9f, 0.9f, 0.3f}))));
    ASSERT_EQ(world.addBlock({{0, 0, 0}, {1, 1, 1}, {}, 0}), AddStatus::Added);
    EXPECT_LT(world.particles().size(), 20u * 20u * 20u);
    EXPECT_EQ(world.countEscapedParticles(), 0u);
}

/// Still water 0.15 m deep over a 1:5 slope in a slice one period of 4 spacings wide, from
/// the lattice.
World waterOverASlope(float spacing) {
    WorldDef def;
    def.domainMax = {0.6f, 0.3f, 4.0f * spacing};
    def.periodic = {false, false, true};
    def.particleSpacing = spacing;
    def.solver.method = "dfsph";
    def.threads = 1;
    World world(def);
    world.addMaterial({});
    world.addObstacle(planeObstacle({0.2f, 0.0f, 0.0f}, {-0.2f, 1.0f, 0.0f}));
    EXPECT_EQ(world.addBlock({{0, 0, 0}, {0.6f, 0.15f, def.domainMax.z}, {}, 0}), AddStatus::Added);
    return world;
}

/// Closest distance from a fluid particle to the particles of obstacle 0, in spacings (the
/// obstacle sampled again as World samples it: on the domain's lattice, a support deep).
float closestToObstacle(const World& world) {
    const WorldDef& def = world.def();
    const float s = def.particleSpacing;
    glm::vec3 clipMin = def.domainMin - 2.0f * s, clipMax = def.domainMax + 2.0f * s;
    clipMin.z = def.domainMin.z;
    clipMax.z = def.domainMax.z;
    const auto solid = sampleObstacle(world.obstacles()[0], def.domainMin, s, def.supportRatio * s, clipMin, clipMax);
    const PeriodicBox periodic = PeriodicBox::make(def.domainMin, def.domainMax, def.periodic);
    float closest = 1e30f;
    for (const glm::vec3& x : world.particles().position)
        for (const glm::vec3& b : solid) closest = std::min(closest, glm::length(periodic.delta(x, b)));
    return closest / s;
}

// A block put against a sloping solid at a spacing its lattice does not fit starts at rest
// density and stays nearly still. The solids' particles sit on the domain's lattice; blocks
// on lattices centred in their boxes sat up to half a spacing off it: pressed against the
// slope's particles (the beach at 1.5 and 1.55 cm reached 9.5 m/s in 0.05 s) or hanging a
// gap above them, into which they fell. The fill also left empty the lattice points within
// half a spacing outside the surface, and the water slid into them along the slope. Before:
// RMS speeds of 0.09-0.16 m/s within 0.2 s and maxima of 0.4-1 m/s; after, 0.010-0.039 and
// 0.07-0.32, the largest where the far wall did not fall on the lattice and the water leaned
// into the gap; with the walls on the lattice (World::Impl::wallsMax) 0.010-0.021 and
// 0.06-0.07.
TEST(World, BlocksStartStillOverASlopeAtAnySpacing) {
    for (const float spacing : {0.02f, 0.0185f, 0.0155f, 0.013f}) {
        World world = waterOverASlope(spacing);
        EXPECT_GT(closestToObstacle(world), 0.999f) << "spacing " << spacing;
        float fastest = 0.0f;
        double rms = 0.0;
        for (int k = 0; k < 4; ++k) {
            world.advance(0.05);
            double sum = 0.0;
            for (const glm::vec3& v : world.particles().velocity) {
                fastest = std::max(fastest, glm::length(v));
                sum += glm::dot(v, v);
            }
            rms = std::max(rms, std::sqrt(sum / world.particles().size()));
        }
        std::printf("spacing %.4f m: %u particles; over 0.2 s, largest RMS speed %.4f m/s, largest speed %.3f m/s\n",
                    spacing, world.particles().size(), rms, fastest);
        EXPECT_LT(rms, 0.03) << "spacing " << spacing;
        EXPECT_LT(fastest, 0.12f) << "spacing " << spacing;
        EXPECT_EQ(world.countEscapedParticles(), 0u);
    }
}

/// Particles of `world` inside obstacle k or outside the domain (independent of countEscapedParticles).
std::uint32_t countInside(const World& world, std::size_t k) {
    std::uint32_t n = 0;
    for (const glm::vec3& x : world.particles().position) n += signedDistance(world.obstacles()[k], x) < 0.0f;
    return n;
}

TEST(World, DamBreakNeverEntersABoxOrAMesh) {
    // The acceptance test: a dam break (dfsph, spacing 0.02) hits a box and the shipped rock;
    // at every frame no particle is inside an obstacle or outside the container.
    WorldDef def;
    def.domainMax = {0.8f, 0.4f, 0.2f};
    def.particleSpacing = 0.02f;
    def.solver.method = "dfsph";
    World world(def);
    world.addMaterial({});
    world.addObstacle(boxObstacle({0.36f, 0.0f, 0.0f}, {0.42f, 0.06f, 0.1f}));
    io::MeshPlacement place;
    place.scale = glm::vec3(0.6f);
    place.rotateDegrees = {0.0f, 30.0f, 0.0f};
    place.translate = {0.6f, 0.0f, 0.12f};
    world.addObstacle(meshObstacle(io::loadMesh(std::string(TIDE_SCENES_DIR) + "/models/rock.obj", place)));
    ASSERT_EQ(world.addBlock({{0, 0, 0}, {0.2f, 0.3f, 0.2f}, {}, 0}), AddStatus::Added);
    ASSERT_EQ(world.particles().size(), 10u * 15u * 10u);
    float reach = 0.0f;
    for (int frame = 1; frame <= 10; ++frame) {
        world.advance(0.1);
        ASSERT_EQ(world.countEscapedParticles(), 0u) << "frame " << frame;
        ASSERT_EQ(countInside(world, 0) + countInside(world, 1), 0u) << "frame " << frame;
        for (const glm::vec3& x : world.particles().position) reach = std::max(reach, x.x);
    }
    EXPECT_GT(reach, 0.7f);  // the water got past both obstacles
}

TEST(World, WaterRunsDownABeachPastAPillar) {
    // A sloping plane (the beach) and a vertical cylinder: nothing gets below or inside.
    WorldDef def;
    def.domainMax = {0.6f, 0.4f, 0.2f};
    def.particleSpacing = 0.02f;
    def.solver.method = "dfsph";
    World world(def);
    world.addMaterial({});
    world.addObstacle(planeObstacle({0.0f, 0.12f, 0.0f}, {0.2f, 1.0f, 0.0f}));
    world.addObstacle(cylinderObstacle({0.4f, 0.2f, 0.1f}, {0, 1, 0}, 0.04f, 0.4f));
    ASSERT_EQ(world.addBlock({{0, 0.12f, 0}, {0.12f, 0.3f, 0.2f}, {}, 0}), AddStatus::Added);
    ASSERT_GT(world.particles().size(), 500u);
    for (int frame = 1; frame <= 5; ++frame) {
        world.advance(0.1);
        ASSERT_EQ(world.countEscapedParticles(), 0u) << "frame " << frame;
    }
}

}  // namespace
