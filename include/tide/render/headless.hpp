#pragma once
/// \file
/// Rendering without a window or display: an EGL context on Mesa's surfaceless platform
/// (software llvmpipe when there is no GPU), and an offscreen image to draw into.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tide::render {

/// An OpenGL 3.3 core context, current on the creating thread, with functions loaded.
/// Throws std::runtime_error saying what is missing when none can be made.
class HeadlessContext {
public:
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    /// GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
    [[nodiscard]] std::string description() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// A width × height RGBA8 framebuffer with depth, to draw into and read back.
class OffscreenImage {
public:
    OffscreenImage(int width, int height);
    ~OffscreenImage();
    OffscreenImage(const OffscreenImage&) = delete;
    OffscreenImage& operator=(const OffscreenImage&) = delete;

    [[nodiscard]] unsigned framebuffer() const { return framebuffer_; }
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }
    /// The pixels, RGBA, top row first (as image files store them).
    [[nodiscard]] std::vector<std::uint8_t> readRgba() const;

private:
    int width_, height_;
    unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
};

}  // namespace tide::render
