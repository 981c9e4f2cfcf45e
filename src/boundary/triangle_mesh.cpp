// Signed distance to a closed triangle mesh.
//
// The distance is that to the nearest triangle (closest point on a triangle: Ericson 2005,
// "Real-Time Collision Detection", §5.1.5), found by a depth-first descent of a bounding-
// volume hierarchy over the triangles that visits the nearer child first and skips any box
// farther than the best triangle so far. The sign is that of (x − c)·n, where c is the
// closest point and n the angle-weighted pseudo-normal of the feature c lies on: the face
// normal inside a face, the sum of the two face normals on an edge, and the sum of the
// incident face normals weighted by their angles at a vertex. Bærentzen & Aanæs 2005,
// "Signed distance computation using the angle weighted pseudonormal" (IEEE TVCG 11(3)),
// prove this sign is right for every point of space when the mesh is a closed 2-manifold,
// which is why the constructor insists on one.
#include <tide/triangle_mesh.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace tide {

namespace {

/// Where on a triangle (a, b, c) its closest point lies.
enum class Feature : std::uint8_t { Face, EdgeAB, EdgeBC, EdgeCA, VertexA, VertexB, VertexC };

/// Closest point on a triangle and the feature it lies on.
struct Closest {
    glm::dvec3 point;
    Feature feature;
};

/// Ericson 2005, §5.1.5: the closest point by Voronoi regions of the vertices, edges and
/// face. In double precision: in float, squared distances of nearby candidates tie when
/// they differ by less than 1e-7 relative, which puts the closest point (and so the normal)
/// off by up to ~3e-4 of the distance.
Closest closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {a, Feature::VertexA};
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return {b, Feature::VertexB};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + (d1 / (d1 - d3)) * ab, Feature::EdgeAB};
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return {c, Feature::VertexC};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {a + (d2 / (d2 - d6)) * ac, Feature::EdgeCA};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return {b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), Feature::EdgeBC};
    const double denominator = 1.0 / (va + vb + vc);
    return {a + (vb * denominator) * ab + (vc * denominator) * ac, Feature::Face};
}

std::string showPoint(const glm::vec3& v) {
    std::ostringstream out;
    out << '[' << v.x << ", " << v.y << ", " << v.z << ']';
    return out.str();
}

/// One side of an edge: triangle `triangle` traverses it from `from` to `to` as its edge `slot`.
struct HalfEdge {
    std::uint64_t key;  ///< min(from, to) << 32 | max(from, to)
    std::uint32_t triangle;
    std::uint8_t slot;  ///< edge k runs from vertex k to vertex (k + 1) % 3
    bool forward;       ///< from < to
};

std::vector<HalfEdge> halfEdgesByEdge(const std::vector<glm::uvec3>& triangles) {
    std::vector<HalfEdge> edges;
    edges.reserve(3 * triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (std::uint8_t k = 0; k < 3; ++k) {
            const std::uint32_t from = triangles[t][k], to = triangles[t][(k + 1) % 3];
            const std::uint64_t lo = std::min(from, to), hi = std::max(from, to);
            edges.push_back({lo << 32 | hi, t, k, from < to});
        }
    std::sort(edges.begin(), edges.end(), [](const HalfEdge& a, const HalfEdge& b) {
        return a.key != b.key ? a.key < b.key : a.triangle < b.triangle;
    });
    return edges;
}

/// Squared distance from x to the box [lo, hi] (0 inside).
float boxDistance2(const glm::vec3& x, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 d = glm::max(glm::max(lo - x, x - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
}

}  // namespace

struct TriangleMesh::Impl {
    /// A BVH node: a leaf holds triangles [first, first + count); an inner node (count 0)
    /// has its left child right after it and its right child at `first`.
    struct Node {
        glm::vec3 lo, hi;
        std::uint32_t first = 0;
        std::uint32_t count = 0;
    };

    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> triangles;             ///< in BVH leaf order
    std::vector<glm::vec3> faceNormal;             ///< unit, per triangle
    std::vector<std::array<glm::vec3, 3>> edgeNormal;  ///< unit pseudo-normal of each triangle's edge k
    std::vector<glm::vec3> vertexNormal;           ///< unit angle-weighted pseudo-normal
    std::vector<Node> nodes;
    glm::vec3 lo{0.0f}, hi{0.0f};
    double volume = 0.0;
    float tinyDistance = 0.0f;  ///< below this, the normal comes from the pseudo-normal

    [[nodiscard]] glm::vec3 pseudoNormal(std::uint32_t t, Feature f) const {
        switch (f) {
            case Feature::Face: return faceNormal[t];
            case Feature::EdgeAB: return edgeNormal[t][0];
            case Feature::EdgeBC: return edgeNormal[t][1];
            case Feature::EdgeCA: return edgeNormal[t][2];
            case Feature::VertexA: return vertexNormal[triangles[t].x];
            case Feature::VertexB: return vertexNormal[triangles[t].y];
            case Feature::VertexC: return vertexNormal[triangles[t].z];
        }
        return faceNormal[t];
    }

    std::uint32_t build(std::vector<std::uint32_t>& order, const std::vector<glm::vec3>& centroid, std::uint32_t begin,
                        std::uint32_t end) {
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        Node node;
        node.lo = glm::vec3(std::numeric_limits<float>::max());
        node.hi = -node.lo;
        glm::vec3 clo = node.lo, chi = node.hi;
        for (std::uint32_t i = begin; i < end; ++i) {
            for (int k = 0; k < 3; ++k) {
                node.lo = glm::min(node.lo, vertices[triangles[order[i]][k]]);
                node.hi = glm::max(node.hi, vertices[triangles[order[i]][k]]);
            }
            clo = glm::min(clo, centroid[order[i]]);
            chi = glm::max(chi, centroid[order[i]]);
        }
        const glm::vec3 extent = chi - clo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (end - begin <= 4 || !(extent[axis] > 0.0f)) {
            node.first = begin;
            node.count = end - begin;
            nodes[index] = node;
            return index;
        }
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) { return centroid[a][axis] < centroid[b][axis]; });
        build(order, centroid, begin, mid);
        node.first = build(order, centroid, mid, end);
        node.count = 0;
        nodes[index] = node;
        return index;
    }

    /// Nearest surface point within sqrt(best2) of x; false if none is nearer.
    bool nearest(const glm::vec3& xf, double& best2, glm::dvec3& closest, glm::vec3& normal) const {
        const glm::dvec3 x(xf);
        bool found = false;
        std::array<std::uint32_t, 64> stack;  // depth ≤ log2(triangles) + 1: median splits
        int top = 0;
        stack[top++] = 0;
        // Boxes are pruned in float, with a little slack so round-off never skips the nearest.
        const auto pruneBelow = [&] { return static_cast<float>(best2) * 1.0001f + 1e-12f; };
        while (top > 0) {
            const Node& node = nodes[stack[--top]];
            if (boxDistance2(xf, node.lo, node.hi) >= pruneBelow()) continue;
            if (node.count > 0) {
                for (std::uint32_t t = node.first; t < node.first + node.count; ++t) {
                    const glm::uvec3& tri = triangles[t];
                    const Closest c = closestOnTriangle(x, glm::dvec3(vertices[tri.x]), glm::dvec3(vertices[tri.y]),
                                                        glm::dvec3(vertices[tri.z]));
                    const glm::dvec3 d = x - c.point;
                    const double d2 = glm::dot(d, d);
                    if (d2 < best2) {
                        best2 = d2;
                        closest = c.point;
                        normal = pseudoNormal(t, c.feature);
                        found = true;
                    }
                }
                continue;
            }
            const std::uint32_t left = static_cast<std::uint32_t>(&node - nodes.data()) + 1, right = node.first;
            const float dl = boxDistance2(xf, nodes[left].lo, nodes[left].hi);
            const float dr = boxDistance2(xf, nodes[right].lo, nodes[right].hi);
            // Push the farther child first so the nearer one is searched first and tightens best2.
            const bool leftFirst = dl <= dr;
            const std::uint32_t nearChild = leftFirst ? left : right, farChild = leftFirst ? right : left;
            if ((leftFirst ? dr : dl) < pruneBelow()) stack[top++] = farChild;
            if ((leftFirst ? dl : dr) < pruneBelow()) stack[top++] = nearChild;
        }
        return found;
    }

    float signedResult(const glm::vec3& xf, double best2, const glm::dvec3& closest, const glm::vec3& pseudo,
                       glm::vec3* normal) const {
        const glm::dvec3 r = glm::dvec3(xf) - closest;
        const double distance = std::sqrt(best2);
        const double sign = glm::dot(r, glm::dvec3(pseudo)) >= 0.0 ? 1.0 : -1.0;
        if (normal) *normal = distance > tinyDistance ? glm::vec3(sign * r / distance) : pseudo;
        return static_cast<float>(sign * distance);
    }
};

TriangleMesh::TriangleMesh(std::vector<glm::vec3> vertices, std::vector<glm::uvec3> triangles)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    if (triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
    for (std::size_t v = 0; v < vertices.size(); ++v)
        if (!std::isfinite(vertices[v].x + vertices[v].y + vertices[v].z))
            throw std::invalid_argument("vertex " + std::to_string(v) + " is not finite: " + showPoint(vertices[v]));
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (triangles[t][k] >= vertices.size())
                throw std::invalid_argument("triangle " + std::to_string(t) + " uses vertex " +
                                            std::to_string(triangles[t][k]) + " of only " +
                                            std::to_string(vertices.size()));

    // Merge vertices at identical positions: formats that split vertices by normal or
    // texture coordinate would otherwise look like a mesh of loose triangles.
    std::vector<std::uint32_t> order(vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto lexicographic = [&](std::uint32_t a, std::uint32_t b) {
        const glm::vec3 &p = vertices[a], &q = vertices[b];
        return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : (p.z != q.z ? p.z < q.z : a < b));
    };
    std::sort(order.begin(), order.end(), lexicographic);
    std::vector<std::uint32_t> merged(vertices.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i == 0 || vertices[order[i]] != vertices[order[i - 1]])
            m.vertices.push_back(vertices[order[i]]);
        merged[order[i]] = static_cast<std::uint32_t>(m.vertices.size() - 1);
    }
    for (glm::uvec3& t : triangles) t = {merged[t.x], merged[t.y], merged[t.z]};

    m.lo = glm::vec3(std::numeric_limits<float>::max());
    m.hi = -m.lo;
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) {
            m.lo = glm::min(m.lo, m.vertices[t[k]]);
            m.hi = glm::max(m.hi, m.vertices[t[k]]);
        }
    const float diagonal = glm::length(m.hi - m.lo);
    m.tinyDistance = 1e-6f * diagonal;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const glm::vec3 &a = m.vertices[triangles[t].x], &b = m.vertices[triangles[t].y], &c = m.vertices[triangles[t].z];
        if (!(glm::length(glm::cross(b - a, c - a)) > 1e-12f * diagonal * diagonal))
            throw std::invalid_argument("triangle " + std::to_string(t) + " is degenerate (no area): " + showPoint(a) +
                                        ", " + showPoint(b) + ", " + showPoint(c));
    }

    // Closed and consistently oriented: each edge has exactly two half-edges, one each way.
    {
        const std::vector<HalfEdge> edges = halfEdgesByEdge(triangles);
        std::size_t holes = 0, crowded = 0, misoriented = 0;
        std::string firstProblem;
        for (std::size_t i = 0; i < edges.size();) {
            std::size_t j = i;
            while (j < edges.size() && edges[j].key == edges[i].key) ++j;
            const std::size_t n = j - i;
            std::size_t* counter = nullptr;
            if (n == 1) counter = &holes;
            else if (n > 2) counter = &crowded;
            else if (edges[i].forward == edges[i + 1].forward) counter = &misoriented;
            if (counter) {
                if (holes + crowded + misoriented == 0) {
                    const glm::vec3 from = m.vertices[edges[i].key >> 32];
                    const glm::vec3 to = m.vertices[edges[i].key & 0xffffffffu];
                    firstProblem = "the edge " + showPoint(from) + " to " + showPoint(to) +
                                   (n == 1   ? " borders only one triangle"
                                    : n > 2  ? " is shared by " + std::to_string(n) + " triangles"
                                             : " joins two triangles facing opposite ways");
                }
                ++*counter;
            }
            i = j;
        }
        if (holes + crowded + misoriented > 0) {
            std::ostringstream out;
            out << "the mesh is not closed and consistently oriented (" << holes << " open edges, " << crowded
                << " edges shared by more than two triangles, " << misoriented << " edges between triangles facing "
                << "opposite ways); e.g. " << firstProblem;
            throw std::invalid_argument(out.str());
        }
    }

    // Divergence theorem: Σ a·(b × c) / 6 over outward-facing triangles is the volume.
    double volume = 0.0;
    const glm::vec3 centre = 0.5f * (m.lo + m.hi);  // subtracting it keeps the sum well conditioned
    for (const glm::uvec3& t : triangles)
        volume += static_cast<double>(glm::dot(m.vertices[t.x] - centre,
                                               glm::cross(m.vertices[t.y] - centre, m.vertices[t.z] - centre)));
    volume /= 6.0;
    if (!(std::abs(volume) > 1e-9 * static_cast<double>(diagonal) * diagonal * diagonal))
        throw std::invalid_argument("the mesh encloses no volume");
    if (volume < 0.0)
        for (glm::uvec3& t : triangles) std::swap(t.y, t.z);
    m.volume = std::abs(volume);

    // Bounding-volume hierarchy; triangles are stored in leaf order.
    std::vector<glm::vec3> centroid(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        centroid[t] = (m.vertices[triangles[t].x] + m.vertices[triangles[t].y] + m.vertices[triangles[t].z]) / 3.0f;
    m.triangles = std::move(triangles);
    std::vector<std::uint32_t> leafOrder(m.triangles.size());
    std::iota(leafOrder.begin(), leafOrder.end(), 0u);
    m.nodes.reserve(2 * m.triangles.size() / 4 + 2);
    m.build(leafOrder, centroid, 0, static_cast<std::uint32_t>(m.triangles.size()));
    std::vector<glm::uvec3> sorted(m.triangles.size());
    for (std::size_t i = 0; i < leafOrder.size(); ++i) sorted[i] = m.triangles[leafOrder[i]];
    m.triangles = std::move(sorted);

    // Pseudo-normals (Bærentzen & Aanæs 2005): faces, edges (sum of the two faces) and
    // vertices (incident faces weighted by their angle at the vertex).
    m.faceNormal.resize(m.triangles.size());
    m.vertexNormal.assign(m.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::uvec3& tri = m.triangles[t];
        const glm::vec3 p[3] = {m.vertices[tri.x], m.vertices[tri.y], m.vertices[tri.z]};
        m.faceNormal[t] = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 u = glm::normalize(p[(k + 1) % 3] - p[k]), w = glm::normalize(p[(k + 2) % 3] - p[k]);
            const float angle = std::acos(std::clamp(glm::dot(u, w), -1.0f, 1.0f));
            m.vertexNormal[tri[k]] += angle * m.faceNormal[t];
        }
    }
    for (glm::vec3& n : m.vertexNormal)
        if (glm::dot(n, n) > 0.0f) n = glm::normalize(n);
    m.edgeNormal.resize(m.triangles.size());
    const std::vector<HalfEdge> edges = halfEdgesByEdge(m.triangles);
    for (std::size_t i = 0; i + 1 < edges.size(); i += 2) {
        const HalfEdge &a = edges[i], &b = edges[i + 1];
        const glm::vec3 sum = m.faceNormal[a.triangle] + m.faceNormal[b.triangle];
        // Two faces folded flat onto each other have no edge normal; either face's will do.
        const glm::vec3 n = glm::dot(sum, sum) > 1e-12f ? glm::normalize(sum) : m.faceNormal[a.triangle];
        m.edgeNormal[a.triangle][a.slot] = n;
        m.edgeNormal[b.triangle][b.slot] = n;
    }
}

TriangleMesh::~TriangleMesh() = default;
TriangleMesh::TriangleMesh(TriangleMesh&&) noexcept = default;
TriangleMesh& TriangleMesh::operator=(TriangleMesh&&) noexcept = default;

float TriangleMesh::signedDistance(const glm::vec3& x, glm::vec3* normal) const {
    double best2 = std::numeric_limits<double>::infinity();
    glm::dvec3 closest{0.0};
    glm::vec3 pseudo{0.0f, 1.0f, 0.0f};
    impl_->nearest(x, best2, closest, pseudo);
    return impl_->signedResult(x, best2, closest, pseudo, normal);
}

bool TriangleMesh::signedDistanceWithin(const glm::vec3& x, float maxDistance, float& distance,
                                        glm::vec3* normal) const {
    double best2 = static_cast<double>(maxDistance) * maxDistance;
    glm::dvec3 closest{0.0};
    glm::vec3 pseudo{0.0f, 1.0f, 0.0f};
    if (!impl_->nearest(x, best2, closest, pseudo)) return false;
    distance = impl_->signedResult(x, best2, closest, pseudo, normal);
    return true;
}

const std::vector<glm::vec3>& TriangleMesh::vertices() const { return impl_->vertices; }
const std::vector<glm::uvec3>& TriangleMesh::triangles() const { return impl_->triangles; }
glm::vec3 TriangleMesh::boundsMin() const { return impl_->lo; }
glm::vec3 TriangleMesh::boundsMax() const { return impl_->hi; }
double TriangleMesh::volume() const { return impl_->volume; }

}  // namespace tide
