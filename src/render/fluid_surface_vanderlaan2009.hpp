#pragma once
// The water surface by screen-space fluid rendering, van der Laan, Green & Sainz 2009,
// "Screen Space Fluid Rendering with Curvature Flow" (I3D '09): render the particles'
// sphere depth, smooth it in screen space, take normals from it, render the thickness, and
// shade each pixel as a water surface over the background. No mesh is ever built.
#include <algorithm>

#include "frame.hpp"
#include "gl.hpp"

namespace tide::render {

/// The water's absorption per metre, of the colours it lacks, in a container of diagonal
/// `extent` m: scaled up for small tanks, so that a tank's worth of water reads as water and
/// not as glass (through 0.2 of the diagonal, red falls to ~e^-1.5).
inline float surfaceAbsorption(float extent) { return 10.0f / std::max(extent, 0.05f); }

class FluidSurfaceVanDerLaan2009 {
public:
    FluidSurfaceVanDerLaan2009();

    /// Draw the fluid over `background` (a texture of the scene without fluid, the frame's
    /// size) into the framebuffer bound by the caller.
    void draw(const Frame& frame, const gl::Texture& background, GLuint target, int smoothingIterations, bool foam);

private:
    void resize(int width, int height);

    gl::Program depth_;
    gl::Program thickness_;
    gl::Program smooth_;
    gl::Program composite_;
    gl::Texture distanceA_, distanceB_, thicknessFoam_, colourSum_;
    gl::Framebuffer depthTarget_, smoothToB_, smoothToA_, thicknessTarget_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace tide::render
