#pragma once

/// @file
/// Reading images from user files. A file's header states its size in a few bytes, and a small file may decode
/// to gigabytes (an 875 KB PNG of 30000 x 30000 pixels needs 2.7 GB as 8-bit RGB): the size in the header is
/// checked against a pixel limit before a single pixel is decoded, and decoder failures become one-line messages
/// that name the file instead of OpenCV's multi-line text.

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace cairn::perception {

/// Largest image (width x height) read from a file unless the caller states another limit: 2^26 = 67,108,864
/// pixels, 8192 x 8192 (six times a Middlebury 2014 full-size view, 128 times VGA).
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 26;

/// What an image file's header says about the image, read without decoding it.
struct ImageFileInfo {
  /// "PNG", "JPEG", "PNM" (PBM/PGM/PPM) or "BMP".
  std::string format;
  /// Size in pixels.
  int width{0};
  /// See width.
  int height{0};
  /// Bits per sample once decoded by OpenCV: 8, or 16 (16-bit PNG, PGM/PPM with a maximum value above 255).
  int bit_depth{8};
  /// Samples per pixel in the file: 1 (grey), 2 (grey + alpha), 3 (colour, palette images included) or 4.
  int channels{1};

  /// width x height, in 64 bits.
  std::int64_t pixels() const { return static_cast<std::int64_t>(width) * height; }
};

/// Reads the header of the image file at `path` (PNG IHDR, JPEG start-of-frame, PNM or BMP header). Throws
/// std::runtime_error naming the file when it cannot be opened or its header is truncated or inconsistent, and
/// std::invalid_argument when it is in another format (TIFF, WebP, ...: convert it to PNG).
ImageFileInfo ReadImageFileInfo(const std::string& path);

/// Decodes the image at `path` with cv::imread(path, flags) after ReadImageFileInfo() has checked its size
/// against `max_pixels`. Throws std::invalid_argument when the image has more than `max_pixels` pixels (the
/// message names its size and the limit) or `max_pixels` is not positive, std::runtime_error naming the file
/// when it is missing, unreadable, corrupt or truncated (never OpenCV's or libpng's own text). As
/// ReadImageFileInfo() for other formats.
cv::Mat ReadImageFile(const std::string& path, int flags, std::int64_t max_pixels = kMaxImagePixels);

}  // namespace cairn::perception
