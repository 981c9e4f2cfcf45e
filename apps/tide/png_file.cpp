// PNG encoding by stb_image_write (Debian's libstb); the file itself by io's atomic writer.
#include "png_file.hpp"

#include <ostream>
#include <stdexcept>

#include <stb/stb_image_write.h>  // implemented by Debian's libstb

#include <tide/io/exporters.hpp>

namespace tide::cli {

void writePng(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
        throw std::runtime_error(file.string() + ": pixel data does not match " + std::to_string(width) + "x" +
                                 std::to_string(height));
    io::writeFileAtomically(file, [&](std::ostream& out) {
        const auto toStream = [](void* context, void* data, int size) {
            static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
        };
        if (!stbi_write_png_to_func(toStream, &out, width, height, 4, rgba.data(), width * 4))
            throw std::runtime_error(file.string() + ": PNG encoding failed");
    });
}

}  // namespace tide::cli
