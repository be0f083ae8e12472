#include "tide/render/png_file.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "tide/io/atomic_file.hpp"

namespace tide::render {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

/// Frees libpng's write and info structures however the function that made them ends.
struct PngWriter {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngWriter() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (png != nullptr) info = png_create_info_struct(png);
  }
  ~PngWriter() { png_destroy_write_struct(&png, info != nullptr ? &info : nullptr); }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
};

void write_png_file(const std::filesystem::path& path, const Image& image) {
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw std::runtime_error(path.string() + ": cannot open for writing");
  PngWriter writer;
  if (writer.png == nullptr || writer.info == nullptr)
    throw std::runtime_error(path.string() + ": cannot start libpng");
  // libpng's own error handler prints the reason and jumps back here. Nothing with a destructor is
  // made between this point and the calls that may jump, so the jump skips no clean-up.
  if (setjmp(png_jmpbuf(writer.png)) != 0) throw std::runtime_error(path.string() + ": libpng cannot write the file");
  png_init_io(writer.png, file.get());
  png_set_IHDR(writer.png, writer.info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
               8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(writer.png, writer.info);
  for (int y = 0; y < image.height; ++y) png_write_row(writer.png, image.at(0, y).data());
  png_write_end(writer.png, nullptr);
  if (std::fflush(file.get()) != 0) throw std::runtime_error(path.string() + ": cannot write the PNG");
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image) {
  static_assert(sizeof(Colour) == 3, "rows are handed to libpng as packed RGB bytes");
  io::replace_atomically(path, [&](const std::filesystem::path& temporary) { write_png_file(temporary, image); });
}

}  // namespace tide::render
