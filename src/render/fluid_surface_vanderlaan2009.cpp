// Screen-space fluid rendering (van der Laan et al. 2009); see the header.
#include "fluid_surface_vanderlaan2009.hpp"

#include <cmath>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "shaders.hpp"

namespace tide::render {

namespace {

std::string sphereVertex() { return std::string(shaders::kVersion) + shaders::kColormap + shaders::kSphereVertex; }
std::string sphereFragment(const char* body) {
    return std::string(shaders::kVersion) + shaders::kSphereFragmentCommon + body;
}
std::string fullscreen() { return std::string(shaders::kVersion) + shaders::kFullscreenVertex; }

}  // namespace

FluidSurfaceVanDerLaan2009::FluidSurfaceVanDerLaan2009()
    : depth_("surface depth", sphereVertex().c_str(), sphereFragment(shaders::kDepthFragment).c_str()),
      thickness_("surface thickness", sphereVertex().c_str(), sphereFragment(shaders::kThicknessFragment).c_str()),
      smooth_("surface smoothing", fullscreen().c_str(),
              (std::string(shaders::kVersion) + shaders::kSmoothFragment).c_str()),
      composite_("surface shading", fullscreen().c_str(),
                 (std::string(shaders::kVersion) + shaders::kSky + shaders::kCompositeFragment).c_str()) {}

void FluidSurfaceVanDerLaan2009::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    distanceA_.allocate(width, height, GL_R32F, GL_RED, GL_FLOAT);
    distanceB_.allocate(width, height, GL_R32F, GL_RED, GL_FLOAT);
    thicknessFoam_.allocate(width, height, GL_RG16F, GL_RG, GL_FLOAT);
    colourSum_.allocate(width, height, GL_RGBA16F, GL_RGBA, GL_FLOAT);
    depthTarget_.attach({&distanceA_}, width, height);
    smoothToB_.attach({&distanceB_});
    smoothToA_.attach({&distanceA_});
    thicknessTarget_.attach({&thicknessFoam_, &colourSum_});
}

void FluidSurfaceVanDerLaan2009::draw(const Frame& frame, const gl::Texture& background, GLuint target,
                                      int smoothingIterations, bool foam) {
    resize(frame.width, frame.height);
    glViewport(0, 0, frame.width, frame.height);

    // 1. Nearest sphere surface per pixel.
    depthTarget_.bind();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    // Obstacles first, depth only: fluid behind them is then not part of the surface.
    if (frame.drawOccluders) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        frame.drawOccluders();
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    depth_.use();
    frame.drawSpheres(depth_);

    // 2. Thickness, foam and colour, summed over every sphere along the ray.
    thicknessTarget_.bind();
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    thickness_.use();
    // A sphere of radius r stands for a particle's volume spacing³: scale the chords so that
    // their sum is the length of fluid along the ray.
    const float sphereVolume = 4.18879f * frame.radius * frame.radius * frame.radius;
    thickness_.set("uThicknessScale", frame.spacing * frame.spacing * frame.spacing / sphereVolume);
    frame.drawSpheres(thickness_);
    glDisable(GL_BLEND);

    // 3. Smooth the depth: horizontal then vertical, ping-ponging A → B → A.
    smooth_.use();
    smooth_.set("uDistance", 0);
    smooth_.set("uPixelRadius", 0.5f * frame.pointScale * frame.radius);
    smooth_.set("uDepthRange", 4.0f * frame.radius);
    for (int i = 0; i < smoothingIterations; ++i) {
        smoothToB_.bind();
        distanceA_.bind(0);
        glUniform2i(smooth_.location("uDirection"), 1, 0);
        gl::drawFullscreenTriangle(frame.emptyVertexArray);
        smoothToA_.bind();
        distanceB_.bind(0);
        glUniform2i(smooth_.location("uDirection"), 0, 1);
        gl::drawFullscreenTriangle(frame.emptyVertexArray);
    }

    // 4. Shade.
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, frame.width, frame.height);
    composite_.use();
    distanceA_.bind(0);
    thicknessFoam_.bind(1);
    background.bind(2);
    colourSum_.bind(3);
    composite_.set("uDistance", 0);
    composite_.set("uThicknessFoam", 1);
    composite_.set("uBackground", 2);
    composite_.set("uColourSum", 3);
    composite_.set("uFoam", foam ? 1.0f : 0.0f);
    composite_.set("uProjection", frame.projection);
    composite_.set("uInverseView", glm::inverse(frame.view));
    composite_.set("uTexel", glm::vec2(1.0f / static_cast<float>(frame.width), 1.0f / static_cast<float>(frame.height)));
    composite_.set("uSunDirection", frame.sunDirection);
    const float tank = std::max(frame.extent, 0.05f);
    composite_.set("uAbsorption", surfaceAbsorption(frame.extent));
    composite_.set("uRefraction", 0.35f / tank);
    glDisable(GL_DEPTH_TEST);
    gl::drawFullscreenTriangle(frame.emptyVertexArray);
}

}  // namespace tide::render
