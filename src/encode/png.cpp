#include "encode/png.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

#include "common/atomic_output.h"
#include "common/error.h"

namespace systole::encode {
namespace {

// libpng reports errors by longjmp. The functions that call setjmp below keep every
// resource in a plain struct owned by their caller, hold no C++ object with a destructor
// between setjmp and libpng's calls, and only return a status; the caller frees and throws.
// So no destructor is skipped and no C++ exception crosses libpng's C frames.
struct PngStatus {
  char message[256] = {};
  char warning[256] = {};  // The last warning: libpng often explains an error there first.
  int io_errno = 0;        // Why the file could not be written (libpng says only "Write Error").
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* status = static_cast<PngStatus*>(png_get_error_ptr(png));
  std::snprintf(status->message, sizeof status->message, "%s", message != nullptr ? message : "unknown error");
  png_longjmp(png, 1);
}

// Warnings (e.g. odd chunks) are not errors; the last one is kept to explain an error.
void on_png_warning(png_structp png, png_const_charp message) {
  auto* status = static_cast<PngStatus*>(png_get_error_ptr(png));
  std::snprintf(status->warning, sizeof status->warning, "%s", message != nullptr ? message : "");
}

std::string describe(const PngStatus& status) {
  if (status.io_errno != 0) return std::strerror(status.io_errno);
  std::string text = status.message[0] != '\0' ? status.message : "out of memory";
  if (status.warning[0] != '\0') text += std::string("; ") + status.warning;
  return text;
}

// Largest side we read (unit: px): a corrupt header must not make us allocate gigabytes.
constexpr png_uint_32 kMaxSide = 16384;

struct Reader {
  FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngStatus status;
  ~Reader() {
    if (png != nullptr) png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr);
    if (file != nullptr) std::fclose(file);
  }
};

// Reads the opened file into `image` as RGB8. Returns false with r.status set on error.
// `image` and `rows` belong to the caller so that a longjmp here skips no destructor.
bool read_rgb(Reader& r, Image& image, std::vector<png_bytep>& rows) {
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.status, on_png_error, on_png_warning);
  if (r.png == nullptr) return false;
  r.info = png_create_info_struct(r.png);
  if (r.info == nullptr) return false;
  if (setjmp(png_jmpbuf(r.png))) return false;

  png_init_io(r.png, r.file);
  png_set_sig_bytes(r.png, 8);
  png_set_user_limits(r.png, kMaxSide, kMaxSide);
  png_read_info(r.png, r.info);

  const png_uint_32 width = png_get_image_width(r.png, r.info);
  const png_uint_32 height = png_get_image_height(r.png, r.info);
  const int color_type = png_get_color_type(r.png, r.info);
  const int bit_depth = png_get_bit_depth(r.png, r.info);
  // Everything to 8-bit RGB: palette and low-bit grey expanded, 16-bit scaled (rounded),
  // grey copied to R, G and B, alpha dropped (colour kept as stored, not composited).
  png_set_expand(r.png);
  if (bit_depth == 16) png_set_scale_16(r.png);
  if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(r.png);
  png_set_strip_alpha(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  if (png_get_rowbytes(r.png, r.info) != static_cast<png_size_t>(width) * 3) {
    std::snprintf(r.status.message, sizeof r.status.message, "unsupported pixel layout");
    return false;
  }

  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  rows.resize(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.row(static_cast<int>(y));
  png_read_image(r.png, rows.data());
  png_read_end(r.png, nullptr);
  return true;
}

struct Writer {
  FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngStatus status;
  ~Writer() {
    if (png != nullptr) png_destroy_write_struct(&png, info != nullptr ? &info : nullptr);
    if (file != nullptr) std::fclose(file);
  }
};

// libpng's own write function reports a failed fwrite as "Write Error" and drops errno:
// these keep it, so a full disk says "No space left on device".
void write_to_file(png_structp png, png_bytep data, png_size_t length) {
  auto* w = static_cast<Writer*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, length, w->file) != length) {
    w->status.io_errno = errno != 0 ? errno : EIO;
    png_error(png, "Write Error");
  }
}

void flush_file(png_structp png) {
  auto* w = static_cast<Writer*>(png_get_io_ptr(png));
  if (std::fflush(w->file) != 0) {
    w->status.io_errno = errno != 0 ? errno : EIO;
    png_error(png, "Flush Error");
  }
}

bool write_rgb(Writer& w, const Image& image, std::vector<png_bytep>& rows) {
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.status, on_png_error, on_png_warning);
  if (w.png == nullptr) return false;
  w.info = png_create_info_struct(w.png);
  if (w.info == nullptr) return false;
  if (setjmp(png_jmpbuf(w.png))) return false;

  png_set_write_fn(w.png, &w, write_to_file, flush_file);
  // Level 3 is several times faster than the default 6 for a few percent more bytes:
  // frame sequences are written at video rate.
  png_set_compression_level(w.png, 3);
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(w.png, w.info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(w.png, w.info);
  rows.resize(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(image.row(y));
  png_write_image(w.png, rows.data());
  png_write_end(w.png, w.info);
  return true;
}

/// Writes `image` to the new file `file` (not atomically: the caller's temporary or staged
/// file). Messages name `shown`, the file the user asked for.
void write_png_file(const std::filesystem::path& file, const std::filesystem::path& shown, const Image& image) {
  if (image.empty() || image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw Error(ExitCode::kInternal, "cannot write '" + shown.string() + "': the image is " +
                                         std::to_string(image.width) + "x" + std::to_string(image.height) +
                                         " with " + std::to_string(image.rgb.size()) + " bytes");
  }
  std::vector<png_bytep> rows;
  Writer w;
  w.file = std::fopen(file.c_str(), "wb");
  if (w.file == nullptr) {
    throw Error(ExitCode::kCannotCreate, "cannot create '" + shown.string() + "': " + std::strerror(errno));
  }
  errno = 0;
  if (!write_rgb(w, image, rows)) {
    throw Error(ExitCode::kIoError, "cannot write '" + shown.string() + "': " + describe(w.status));
  }
  FILE* written = w.file;
  w.file = nullptr;
  // fclose flushes: a full disk shows here.
  if (std::ferror(written) != 0 || std::fclose(written) != 0) {
    throw Error(ExitCode::kIoError, "cannot write '" + shown.string() + "': " + std::strerror(errno));
  }
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image) {
  AtomicOutput output(path);
  write_png_file(output.temp_path(), path, image);
  output.commit();
}

Image read_png(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw Error(ExitCode::kNoInput, "cannot read '" + path.string() + "': " +
                                        (std::filesystem::exists(path, ec) ? "not a file" : "no such file"));
  }
  Reader r;
  r.file = std::fopen(path.c_str(), "rb");
  if (r.file == nullptr) {
    throw Error(ExitCode::kNoInput, "cannot read '" + path.string() + "': " + std::strerror(errno));
  }
  unsigned char signature[8] = {};
  if (std::fread(signature, 1, sizeof signature, r.file) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw Error(ExitCode::kDataError, "cannot read '" + path.string() + "': not a PNG file");
  }
  Image image;
  std::vector<png_bytep> rows;
  if (!read_rgb(r, image, rows)) {
    throw Error(ExitCode::kDataError, "cannot read '" + path.string() + "': corrupt PNG (" + describe(r.status) + ")");
  }
  return image;
}

std::string frame_file_name(int index, int frame_count) {
  if (index < 0) throw Error(ExitCode::kInternal, "negative frame index " + std::to_string(index));
  int digits = 5;
  for (long long limit = 100000; limit < frame_count; limit *= 10) ++digits;
  std::string number = std::to_string(index);
  if (number.size() < static_cast<std::size_t>(digits)) number.insert(0, digits - number.size(), '0');
  return "frame_" + number + ".png";
}

PngSequenceWriter::PngSequenceWriter(const std::filesystem::path& folder, int frame_count)
    : update_(folder), frame_count_(frame_count) {}

void PngSequenceWriter::write(const Image& image, int frame_index) {
  const std::string name = frame_file_name(frame_index, frame_count_);
  write_png_file(update_.staged_path(name), update_.folder() / name, image);
}

void PngSequenceWriter::finish() { update_.commit(); }

}  // namespace systole::encode
