#include "cairn/common/number_text.h"
#include "cairn/perception/io/image_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

namespace cairn::perception {
namespace {

// A file may hold at most this many bytes per allowed pixel (16-bit RGBA stored without compression is 8), plus
// this much for metadata: bounds the read of the whole file before its header is even parsed.
constexpr std::int64_t kMaxFileBytesPerPixel = 16;
constexpr std::int64_t kFileBytesSlack = std::int64_t{1} << 20;

// The whole file, read once: the header is parsed from it, its structure checked, and the same bytes decoded.
std::vector<uchar> LoadBytes(const std::string& path, std::int64_t max_pixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open image '" + path + "': no such readable file; check the path");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0 || !in) throw std::runtime_error("cannot read image '" + path + "'; check that it is a regular file");
  const std::int64_t max_bytes = kMaxFileBytesPerPixel * max_pixels + kFileBytesSlack;
  if (static_cast<std::int64_t>(size) > max_bytes) {
    throw std::invalid_argument("image file '" + path + "' has " + cairn::FormatShort(size) + " bytes, more than the " +
                                cairn::FormatShort(max_bytes) + " an image of at most " + cairn::FormatShort(max_pixels) +
                                " pixels may take; downscale or crop it");
  }
  std::vector<uchar> bytes(static_cast<std::size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size)) {
    throw std::runtime_error("cannot read image '" + path + "': the read stopped after " +
                             cairn::FormatShort(in.gcount()) + " of " + cairn::FormatShort(size) + " bytes");
  }
  return bytes;
}

// Reads a header out of the file's bytes; every read past the end reports a truncated header.
class HeaderBytes {
 public:
  HeaderBytes(const std::vector<uchar>& bytes, const std::string& path, std::string format)
      : bytes_(bytes), path_(path), format_(std::move(format)) {}

  [[noreturn]] void Corrupt(const std::string& what) const {
    throw std::runtime_error("image '" + path_ + "' has a broken " + format_ + " header (" + what +
                             "); the file is corrupt or truncated");
  }
  [[noreturn]] void Truncated(const std::string& what) const {
    throw std::runtime_error(format_ + " image '" + path_ + "' is truncated or corrupt (" + what + ")");
  }

  std::size_t position() const { return position_; }
  std::size_t size() const { return bytes_.size(); }
  const uchar* data() const { return bytes_.data(); }

  int Byte() {
    if (position_ >= bytes_.size()) Corrupt("it ends early");
    return bytes_[position_++];
  }
  std::uint32_t BigEndian(int count) {
    std::uint32_t value = 0;
    for (int i = 0; i < count; ++i) value = (value << 8) | static_cast<std::uint32_t>(Byte());
    return value;
  }
  std::uint32_t LittleEndian(int count) {
    std::uint32_t value = 0;
    for (int i = 0; i < count; ++i) value |= static_cast<std::uint32_t>(Byte()) << (8 * i);
    return value;
  }
  void Skip(std::uint64_t count) {
    if (count > bytes_.size() - position_) Corrupt("it ends early");
    position_ += static_cast<std::size_t>(count);
  }

  // A size from a header, which must fit OpenCV's int sizes.
  int Dimension(std::uint64_t value, const char* what) const {
    if (value == 0 || value > 0x7fffffffu) Corrupt(std::string(what) + " " + cairn::FormatShort(value));
    return static_cast<int>(value);
  }

 private:
  const std::vector<uchar>& bytes_;
  const std::string& path_;
  std::string format_;
  std::size_t position_{0};
};

// CRC-32 (ISO 3309, as PNG uses it) of `size` bytes.
std::uint32_t Crc32(const uchar* data, std::size_t size) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

// PNG: the IHDR chunk follows the 8-byte signature (PNG specification, 11.2.2). With `check_chunks`, every chunk
// up to IEND must lie within the file with a matching CRC: libpng would otherwise print its own error on a
// truncated or damaged file before OpenCV gives up.
ImageFileInfo ReadPng(HeaderBytes* bytes, bool check_chunks) {
  ImageFileInfo info;
  info.format = "PNG";
  bytes->Skip(8);
  if (bytes->BigEndian(4) != 13) bytes->Corrupt("the first chunk is not a 13-byte IHDR");
  std::string type;
  for (int i = 0; i < 4; ++i) type += static_cast<char>(bytes->Byte());
  if (type != "IHDR") bytes->Corrupt("the first chunk is '" + type + "', not IHDR");
  info.width = bytes->Dimension(bytes->BigEndian(4), "width");
  info.height = bytes->Dimension(bytes->BigEndian(4), "height");
  const int depth = bytes->Byte();
  const int colour = bytes->Byte();
  if (depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16) {
    bytes->Corrupt("bit depth " + cairn::FormatShort(depth));
  }
  info.bit_depth = depth == 16 ? 16 : 8;
  switch (colour) {
    case 0: info.channels = 1; break;
    case 2: info.channels = 3; break;
    case 3: info.channels = 3; break;  // palette entries are RGB
    case 4: info.channels = 2; break;
    case 6: info.channels = 4; break;
    default: bytes->Corrupt("colour type " + cairn::FormatShort(colour));
  }
  if (!check_chunks) return info;
  std::size_t at = 8;
  for (;;) {
    if (bytes->size() - at < 12) bytes->Truncated("the file ends before its IEND chunk");
    const uchar* chunk = bytes->data() + at;
    const std::uint64_t length = (std::uint64_t{chunk[0]} << 24) | (std::uint64_t{chunk[1]} << 16) |
                                 (std::uint64_t{chunk[2]} << 8) | chunk[3];
    if (length > bytes->size() - at - 12) bytes->Truncated("a chunk runs past the end of the file");
    const std::uint32_t stored = (std::uint32_t{chunk[8 + length]} << 24) | (std::uint32_t{chunk[9 + length]} << 16) |
                                 (std::uint32_t{chunk[10 + length]} << 8) | chunk[11 + length];
    if (Crc32(chunk + 4, static_cast<std::size_t>(length) + 4) != stored) {
      bytes->Truncated("chunk '" + std::string(reinterpret_cast<const char*>(chunk + 4), 4) + "' fails its CRC check");
    }
    if (std::equal(chunk + 4, chunk + 8, "IEND")) return info;
    at += static_cast<std::size_t>(length) + 12;
  }
}

// JPEG: walks the marker segments up to the first start-of-frame (ITU T.81, B.2.2). With `check_end`, an
// end-of-image marker must follow the first scan: libjpeg would otherwise print a warning and OpenCV return an
// image whose missing rows are grey.
ImageFileInfo ReadJpeg(HeaderBytes* bytes, bool check_end) {
  ImageFileInfo info;
  info.format = "JPEG";
  bytes->Skip(2);
  bool have_frame = false;
  for (;;) {
    int marker = bytes->Byte();
    if (marker != 0xFF) bytes->Corrupt("a segment does not start with a marker");
    while (marker == 0xFF) marker = bytes->Byte();  // fill bytes
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) continue;  // no length field
    if (marker == 0xD9) bytes->Corrupt("the image ends before its first scan");
    const std::uint32_t length = bytes->BigEndian(2);
    if (length < 2) bytes->Corrupt("a segment of length " + cairn::FormatShort(length));
    if (marker == 0xDA) {
      if (!have_frame) bytes->Corrupt("no frame header before the image data");
      break;
    }
    const bool start_of_frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (!start_of_frame || have_frame) {
      bytes->Skip(length - 2);
      continue;
    }
    if (length < 8) bytes->Corrupt("a frame header of length " + cairn::FormatShort(length));
    const int precision = bytes->Byte();
    const std::uint32_t height = bytes->BigEndian(2);
    const std::uint32_t width = bytes->BigEndian(2);
    const int components = bytes->Byte();
    if (height == 0) bytes->Corrupt("height 0, to be given by a later DNL marker, which is not supported");
    info.height = bytes->Dimension(height, "height");
    info.width = bytes->Dimension(width, "width");
    info.bit_depth = precision > 8 ? 16 : 8;
    if (components < 1 || components > 4) bytes->Corrupt(cairn::FormatShort(components) + " components");
    info.channels = components;
    have_frame = true;
    bytes->Skip(length - 8);
    if (!check_end) return info;
  }
  // Inside entropy-coded data 0xFF is always followed by 0x00 or a restart marker, so FF D9 is the end.
  const uchar* begin = bytes->data() + bytes->position();
  const uchar* end = bytes->data() + bytes->size();
  const uchar eoi[] = {0xFF, 0xD9};
  if (std::search(begin, end, eoi, eoi + 2) == end) bytes->Truncated("no end-of-image marker after the image data");
  return info;
}

// PNM: "P1".."P6", then width, height and (except for bitmaps) the maximum value, separated by whitespace and
// '#' comments (netpbm's pbm, pgm and ppm formats). With `check_size`, a binary file must hold every pixel.
ImageFileInfo ReadPnm(HeaderBytes* bytes, int kind, bool check_size) {
  ImageFileInfo info;
  info.format = "PNM";
  bytes->Skip(2);
  int c = ' ';
  auto number = [&](const char* what) {
    c = bytes->Byte();
    for (;;) {
      if (c == '#') {
        while (c != '\n' && c != '\r') c = bytes->Byte();
      } else if (std::isspace(c)) {
        c = bytes->Byte();
      } else {
        break;
      }
    }
    std::uint64_t value = 0;
    int digits = 0;
    while (std::isdigit(c)) {
      if (++digits > 10) bytes->Corrupt(std::string("the ") + what + " has more than 10 digits");
      value = 10 * value + static_cast<std::uint64_t>(c - '0');
      c = bytes->Byte();
    }
    if (digits == 0) bytes->Corrupt(std::string("no ") + what);
    return value;
  };
  info.width = bytes->Dimension(number("width"), "width");
  info.height = bytes->Dimension(number("height"), "height");
  const bool bitmap = kind == 1 || kind == 4;
  if (!bitmap) {
    const std::uint64_t max_value = number("maximum value");
    if (max_value == 0 || max_value > 65535) bytes->Corrupt("maximum value " + cairn::FormatShort(max_value));
    info.bit_depth = max_value > 255 ? 16 : 8;
  }
  info.channels = kind == 3 || kind == 6 ? 3 : 1;
  if (check_size && kind >= 4) {
    // One whitespace byte ends the header; then the raster.
    const std::uint64_t row = kind == 4 ? (static_cast<std::uint64_t>(info.width) + 7) / 8
                                        : static_cast<std::uint64_t>(info.width) * info.channels * (info.bit_depth / 8);
    const std::uint64_t needed = row * static_cast<std::uint64_t>(info.height);
    if (bytes->size() - bytes->position() < needed) {
      bytes->Truncated("the raster needs " + cairn::FormatShort(needed) + " bytes, the file holds " +
                       cairn::FormatShort(bytes->size() - bytes->position()));
    }
  }
  return info;
}

// BMP: the file header, then the DIB header's size, width, height, planes and bits per pixel. With
// `check_size`, an uncompressed file must hold every row.
ImageFileInfo ReadBmp(HeaderBytes* bytes, bool check_size) {
  ImageFileInfo info;
  info.format = "BMP";
  bytes->Skip(10);  // magic, file size, reserved
  const std::uint32_t pixel_offset = bytes->LittleEndian(4);
  const std::uint32_t header_size = bytes->LittleEndian(4);
  std::int64_t width = 0;
  std::int64_t height = 0;
  if (header_size == 12) {  // BITMAPCOREHEADER
    width = bytes->LittleEndian(2);
    height = bytes->LittleEndian(2);
  } else if (header_size >= 40) {
    width = static_cast<std::int32_t>(bytes->LittleEndian(4));
    height = static_cast<std::int32_t>(bytes->LittleEndian(4));
  } else {
    bytes->Corrupt("a DIB header of " + cairn::FormatShort(header_size) + " bytes");
  }
  bytes->Skip(2);  // planes
  const std::uint32_t bits = bytes->LittleEndian(2);
  const std::uint32_t compression = header_size >= 40 ? bytes->LittleEndian(4) : 0;
  if (height < 0) height = -height;  // rows stored top-down
  if (width <= 0) bytes->Corrupt("width " + cairn::FormatShort(width));
  info.width = bytes->Dimension(static_cast<std::uint64_t>(width), "width");
  info.height = bytes->Dimension(static_cast<std::uint64_t>(height), "height");
  if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32) {
    bytes->Corrupt(cairn::FormatShort(bits) + " bits per pixel");
  }
  info.channels = bits == 32 ? 4 : 3;  // palette and 16-bit images decode to BGR
  if (check_size && compression == 0) {
    const std::uint64_t row = (static_cast<std::uint64_t>(info.width) * bits + 31) / 32 * 4;
    const std::uint64_t needed = static_cast<std::uint64_t>(pixel_offset) + row * static_cast<std::uint64_t>(info.height);
    if (bytes->size() < needed) {
      bytes->Truncated("the rows need " + cairn::FormatShort(needed) + " bytes, the file has " +
                       cairn::FormatShort(bytes->size()));
    }
  }
  return info;
}

// The header of `bytes`, and with `check_structure` the checks that keep decoders from printing their own
// errors or returning partial images.
ImageFileInfo ParseHeader(const std::vector<uchar>& bytes, const std::string& path, bool check_structure) {
  if (bytes.size() < 2) throw std::runtime_error("image '" + path + "' is empty or shorter than any image header");
  const std::array<uchar, 8> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes[0] == 0x89 && bytes[1] == 'P') {
    HeaderBytes header(bytes, path, "PNG");
    if (bytes.size() < png.size() || !std::equal(png.begin(), png.end(), bytes.begin())) {
      header.Corrupt("bad signature");
    }
    return ReadPng(&header, check_structure);
  }
  if (bytes[0] == 0xFF && bytes[1] == 0xD8) {
    HeaderBytes header(bytes, path, "JPEG");
    return ReadJpeg(&header, check_structure);
  }
  if (bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') {
    HeaderBytes header(bytes, path, "PNM");
    return ReadPnm(&header, bytes[1] - '0', check_structure);
  }
  if (bytes[0] == 'B' && bytes[1] == 'M') {
    HeaderBytes header(bytes, path, "BMP");
    return ReadBmp(&header, check_structure);
  }
  throw std::invalid_argument("image '" + path +
                              "' is not a PNG, JPEG, PNM (PBM/PGM/PPM) or BMP file; convert it to PNG");
}

}  // namespace

ImageFileInfo ReadImageFileInfo(const std::string& path) {
  return ParseHeader(LoadBytes(path, kMaxImagePixels), path, false);
}

cv::Mat ReadImageFile(const std::string& path, int flags, std::int64_t max_pixels) {
  if (max_pixels <= 0 || max_pixels > (std::int64_t{1} << 40)) {
    throw std::invalid_argument("ReadImageFile: the pixel limit " + cairn::FormatShort(max_pixels) +
                                " must be positive and at most 2^40 (the default is " +
                                cairn::FormatShort(kMaxImagePixels) + ")");
  }
  const std::vector<uchar> bytes = LoadBytes(path, max_pixels);
  // The size first, from the header alone, so that the message names it even for an otherwise damaged file.
  const ImageFileInfo info = ParseHeader(bytes, path, false);
  if (info.pixels() > max_pixels) {
    throw std::invalid_argument("image '" + path + "' is " + cairn::FormatShort(info.width) + " x " +
                                cairn::FormatShort(info.height) + " = " + cairn::FormatShort(info.pixels()) +
                                " pixels, more than the limit of " + cairn::FormatShort(max_pixels) +
                                " pixels; downscale or crop it");
  }
  ParseHeader(bytes, path, true);
  cv::Mat image;
  try {
    image = cv::imdecode(bytes, flags);
  } catch (const cv::Exception&) {
    image.release();  // reported below, in one line, with the file's name
  }
  if (image.empty()) {
    throw std::runtime_error("cannot decode " + info.format + " image '" + path + "' (" + cairn::FormatShort(info.width) +
                             " x " + cairn::FormatShort(info.height) + " in its header); the file is corrupt");
  }
  return image;
}

}  // namespace cairn::perception
