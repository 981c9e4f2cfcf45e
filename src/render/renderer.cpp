// The renderer: particle buffers, the background (sky, ground, container), sphere impostors,
// and the water surface pass.
#include <tide/render/renderer.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "far_field_sea.hpp"
#include "fluid_surface_vanderlaan2009.hpp"
#include "frame.hpp"
#include "gl.hpp"
#include "obstacle_mesh.hpp"
#include "shaders.hpp"

namespace tide::render {

namespace {

constexpr glm::vec3 kColormapStops[5] = {
    {0.267f, 0.005f, 0.329f}, {0.229f, 0.322f, 0.546f}, {0.128f, 0.567f, 0.551f},
    {0.369f, 0.789f, 0.383f}, {0.993f, 0.906f, 0.144f}};


template <typename T>
void upload(GLuint buffer, const std::vector<T>& data) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STREAM_DRAW);
}

}  // namespace

glm::vec3 colormap(float t) {
    t = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(static_cast<int>(t), 3);
    return glm::mix(kColormapStops[i], kColormapStops[i + 1], t - static_cast<float>(i));
}

const char* colorByName(ColorBy colorBy) {
    switch (colorBy) {
        case ColorBy::Material: return "material";
        case ColorBy::Speed: return "speed (m/s)";
        case ColorBy::Density: return "density (kg/m3)";
        case ColorBy::Pressure: return "pressure (Pa)";
    }
    return "";
}

struct Renderer::Impl {
    gl::Program background{"background", shaders::compose({shaders::kFullscreenVertex}).c_str(),
                           shaders::compose({shaders::kSky, shaders::kDeepWater, shaders::kBackgroundFragment}).c_str()};
    gl::Program lines{"container", shaders::compose({shaders::kLinesVertex}).c_str(), shaders::compose({shaders::kLinesFragment}).c_str()};
    gl::Program particles{"particles", shaders::compose({shaders::kColormap, shaders::kSphereVertex}).c_str(),
                          shaders::compose({shaders::kSphereFragmentCommon, shaders::kParticleFragment}).c_str()};
    gl::Program solids{"obstacles", shaders::compose({shaders::kSolidVertex}).c_str(), shaders::compose({shaders::kSolidFragment}).c_str()};
    FluidSurfaceVanDerLaan2009 surface;
    FarFieldSea farField;

    GLuint emptyVertexArray = 0;
    GLuint particleArray = 0;
    GLuint buffers[5] = {};  // position, velocity, density, pressure, material
    GLuint boxArray = 0;
    GLuint boxBuffer = 0;
    GLuint solidArray = 0;
    GLuint solidBuffer = 0;
    GLsizei solidVertices = 0;
    std::uint64_t uploadedVersion = std::numeric_limits<std::uint64_t>::max();
    const Snapshot* uploadedFrom = nullptr;
    GLsizei count = 0;
    glm::vec2 range{0.0f, 1.0f};

    // The scene without the fluid, for the surface pass to refract.
    gl::Texture backgroundColour;
    gl::Framebuffer backgroundTarget;
    int width = 0, height = 0;

    Impl() {
        glGenVertexArrays(1, &emptyVertexArray);
        glGenVertexArrays(1, &particleArray);
        glGenBuffers(5, buffers);
        glBindVertexArray(particleArray);
        const GLint components[4] = {3, 3, 1, 1};
        for (GLuint a = 0; a < 4; ++a) {
            glBindBuffer(GL_ARRAY_BUFFER, buffers[a]);
            glEnableVertexAttribArray(a);
            glVertexAttribPointer(a, components[a], GL_FLOAT, GL_FALSE, 0, nullptr);
        }
        glBindBuffer(GL_ARRAY_BUFFER, buffers[4]);
        glEnableVertexAttribArray(4);
        static_assert(sizeof(MaterialIndex) == 2);
        glVertexAttribIPointer(4, 1, GL_UNSIGNED_SHORT, 0, nullptr);
        glGenVertexArrays(1, &boxArray);
        glGenBuffers(1, &boxBuffer);
        glBindVertexArray(boxArray);
        glBindBuffer(GL_ARRAY_BUFFER, boxBuffer);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glGenVertexArrays(1, &solidArray);
        glGenBuffers(1, &solidBuffer);
        glBindVertexArray(solidArray);
        glBindBuffer(GL_ARRAY_BUFFER, solidBuffer);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(SolidVertex), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(SolidVertex),
                              reinterpret_cast<const void*>(offsetof(SolidVertex, normal)));
        glBindVertexArray(0);
    }

    ~Impl() {
        glDeleteBuffers(1, &solidBuffer);
        glDeleteVertexArrays(1, &solidArray);
        glDeleteBuffers(5, buffers);
        glDeleteBuffers(1, &boxBuffer);
        glDeleteVertexArrays(1, &particleArray);
        glDeleteVertexArrays(1, &boxArray);
        glDeleteVertexArrays(1, &emptyVertexArray);
    }

    void uploadParticles(const Snapshot& s) {
        if (s.version == uploadedVersion && &s == uploadedFrom) return;
        upload(buffers[0], s.position);
        upload(buffers[1], s.velocity);
        upload(buffers[2], s.density);
        upload(buffers[3], s.pressure);
        upload(buffers[4], s.material);
        count = static_cast<GLsizei>(s.size());
        uploadedVersion = s.version;
        uploadedFrom = &s;

        const glm::vec3 lo = s.domainMin, hi = s.domainMax;
        const glm::vec3 corners[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                                      {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
        const int edges[24] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6, 3, 7};
        std::vector<glm::vec3> vertices;
        for (int e : edges) vertices.push_back(corners[e]);
        upload(boxBuffer, vertices);
        // Cheap to tessellate again with each new state, where moving obstacles are now.
        const std::vector<SolidVertex> solid = tessellate(s.obstacles, 2.0f * glm::length(hi - lo), s.obstaclePoses);
        upload(solidBuffer, solid);
        solidVertices = static_cast<GLsizei>(solid.size());
    }

    glm::vec2 autoRange(const Snapshot& s, ColorBy by) const {
        float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
        for (std::uint32_t i = 0; i < s.size(); ++i) {
            const float v = by == ColorBy::Speed ? glm::length(s.velocity[i])
                            : by == ColorBy::Density ? s.density[i]
                                                     : s.pressure[i];
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        if (s.size() == 0) return {0.0f, 1.0f};
        if (by == ColorBy::Speed) lo = 0.0f;
        if (hi - lo < 1e-6f) hi = lo + 1.0f;
        return {lo, hi};
    }

    /// How the near field's water (material 0, or its override) is shaded: the far field's too.
    static WaterLook waterLook(const Frame& f, const Snapshot& s, const RenderSettings& r) {
        WaterLook look;
        if (r.color[0].r >= 0.0f) look.color = r.color[0];
        else if (!s.materials.empty()) look.color = s.materials[0].color;
        look.absorption = surfaceAbsorption(f.extent);
        look.fogDistance = 12.0f * f.extent;
        // The drawn surface is the spheres' envelope: the top layer's centres (half a spacing
        // under the water's surface) plus the sprite radius.
        look.surfaceLift = r.mode == RenderMode::Surface ? f.radius - 0.5f * f.spacing : 0.0f;
        return look;
    }

    void drawBackground(const Frame& f, const Camera& camera, const Snapshot& s, const RenderSettings& r) {
        const glm::mat4 viewProjection = f.projection * f.view;
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
        background.use();
        background.set("uInverseViewProjection", glm::inverse(viewProjection));
        background.set("uViewProjection", viewProjection);
        background.set("uEye", camera.eye);
        background.set("uTexel", glm::vec2(1.0f / static_cast<float>(f.width), 1.0f / static_cast<float>(f.height)));
        background.set("uGroundY", s.domainMin.y);
        // Tiles a fifth of the container's width: a scale reference under the water.
        const glm::vec3 size = s.domainMax - s.domainMin;
        background.set("uTile", std::max(0.2f * std::max(size.x, size.z), 1e-3f));
        background.set("uFogDistance", 12.0f * f.extent);
        background.set("uSunDirection", f.sunDirection);
        background.set("uOcean", s.ocean ? 1 : 0);
        background.set("uSeaY", s.domainMin.y + (s.ocean ? static_cast<float>(s.ocean->depth) : 0.0f) + waterLook(f, s, r).surfaceLift);
        background.set("uNearMin", glm::vec2(s.domainMin.x, s.domainMin.z));
        background.set("uNearMax", glm::vec2(s.domainMax.x, s.domainMax.z));
        const WaterLook water = waterLook(f, s, r);
        background.set("uWaterColor", water.color);
        background.set("uAbsorption", water.absorption);
        background.set("uSeaDepth", s.ocean ? static_cast<float>(s.ocean->depth) : 0.0f);
        gl::drawFullscreenTriangle(emptyVertexArray);
        glDepthFunc(GL_LESS);
        farField.draw(f, camera, s, water);
        drawSolids(f);
        if (r.showContainer) {
            lines.use();
            lines.set("uViewProjection", viewProjection);
            lines.set("uColor", glm::vec3(0.25f, 0.27f, 0.3f));
            glBindVertexArray(boxArray);
            glDrawArrays(GL_LINES, 0, 24);
        }
    }

    /// An ocean's far field over the coupling zones of the shaded surface in the bound
    /// framebuffer (FarFieldSea::draw with `zones`), hidden by the solids and by its own waves.
    void blendZones(const Frame& f, const Camera& camera, const Snapshot& s, const RenderSettings& r) {
        if (!farField.active()) return;
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glClear(GL_DEPTH_BUFFER_BIT);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawSolids(f);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glEnable(GL_BLEND);
        // The frame's alpha stays (1): PNG frames carry it.
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        farField.draw(f, camera, s, waterLook(f, s, r), true);
        glDisable(GL_BLEND);
    }

    void drawSolids(const Frame& f) {
        if (solidVertices == 0) return;
        solids.use();
        solids.set("uViewProjection", f.projection * f.view);
        solids.set("uSunDirection", f.sunDirection);
        glBindVertexArray(solidArray);
        glDrawArrays(GL_TRIANGLES, 0, solidVertices);
    }

    void setSphereUniforms(const gl::Program& p, const Frame& f, const Snapshot& s, const RenderSettings& r) const {
        p.set("uView", f.view);
        p.set("uProjection", f.projection);
        p.set("uRadius", f.radius);
        p.set("uPointScale", f.pointScale);
        unsigned visible = 0;
        for (int m = 0; m < kMaxRenderMaterials; ++m)
            if (r.visible[static_cast<std::size_t>(m)]) visible |= 1u << m;
        p.set("uVisible", visible);
        p.set("uColorBy", static_cast<int>(r.colorBy));
        p.set("uRange", range);
        glm::vec3 colours[kMaxRenderMaterials];
        float rest[kMaxRenderMaterials];
        for (std::size_t m = 0; m < kMaxRenderMaterials; ++m) {
            const bool known = m < s.materials.size();
            colours[m] = r.color[m].r >= 0.0f ? r.color[m] : known ? s.materials[m].color : glm::vec3(0.7f);
            rest[m] = known ? s.materials[m].restDensity : 1000.0f;
        }
        glUniform3fv(p.location("uMaterialColor"), kMaxRenderMaterials, &colours[0].x);
        glUniform1fv(p.location("uRestDensity"), kMaxRenderMaterials, rest);
        glUniform3fv(p.location("uColormap"), 5, &kColormapStops[0].x);
        // Whitecaps from a fraction of the speed a fall through the container's height gives.
        const float fallSpeed = std::sqrt(2.0f * 9.81f * std::max(s.domainMax.y - s.domainMin.y, 1e-3f));
        p.set("uFoamSpeed", glm::vec2(0.6f, 1.2f) * fallSpeed);
        glBindVertexArray(particleArray);
        glDrawArrays(GL_POINTS, 0, count);
    }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

glm::vec2 Renderer::lastRange() const { return impl_->range; }

void Renderer::draw(const Snapshot& snapshot, const Camera& camera, const RenderSettings& settings, int width,
                    int height, unsigned framebuffer) {
    Impl& d = *impl_;
    d.uploadParticles(snapshot);
    d.farField.update(snapshot, camera);
    if (settings.colorBy != ColorBy::Material)
        d.range = settings.range.x < settings.range.y ? settings.range : d.autoRange(snapshot, settings.colorBy);

    Frame f;
    f.width = width;
    f.height = height;
    f.view = viewMatrix(camera);
    f.projection = projectionMatrix(camera, static_cast<float>(width) / static_cast<float>(height));
    f.spacing = snapshot.particleSpacing;
    // Surface spheres overlap more than the particles' own size so the depth has no holes.
    const float radiusFactor = settings.mode == RenderMode::Surface ? 1.0f : 0.5f;
    f.radius = radiusFactor * settings.particleScale * snapshot.particleSpacing;
    f.pointScale = static_cast<float>(height) * f.projection[1][1];
    f.extent = glm::length(snapshot.domainMax - snapshot.domainMin);
    f.sunDirection = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));
    f.emptyVertexArray = d.emptyVertexArray;
    f.drawSpheres = [&](const gl::Program& p) { d.setSphereUniforms(p, f, snapshot, settings); };
    // The far field's waves can hide near-field water behind them too.
    f.drawOccluders = [&] {
        d.drawSolids(f);
        d.farField.draw(f, camera, snapshot, Impl::waterLook(f, snapshot, settings));
    };

    glEnable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    if (settings.mode == RenderMode::Particles) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, width, height);
        glClear(GL_DEPTH_BUFFER_BIT);
        d.drawBackground(f, camera, snapshot, settings);
        d.particles.use();
        d.particles.set("uLightDirection", glm::normalize(glm::mat3(f.view) * f.sunDirection));
        f.drawSpheres(d.particles);
    } else {
        if (d.width != width || d.height != height) {
            d.backgroundColour.allocate(width, height, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, true);
            d.backgroundTarget.attach({&d.backgroundColour}, width, height);
            d.width = width;
            d.height = height;
        }
        d.backgroundTarget.bind();
        glViewport(0, 0, width, height);
        glClear(GL_DEPTH_BUFFER_BIT);
        d.drawBackground(f, camera, snapshot, settings);
        d.surface.draw(f, d.backgroundColour, framebuffer, std::max(settings.smoothingIterations, 0), settings.foam);
        d.blendZones(f, camera, snapshot, settings);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace tide::render
