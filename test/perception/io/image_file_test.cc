#include "cairn/perception/io/image_file.h"

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

std::string Scratch(const std::string& name) { return testing::TempDir() + "image_file_test_" + name; }

void WriteBytes(const std::string& path, const std::vector<uchar>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::vector<uchar> Encode(const std::string& extension, const cv::Mat& image) {
  std::vector<uchar> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes));
  return bytes;
}

cv::Mat Ramp(int rows, int cols, int type) {
  cv::Mat image(rows, cols, type);
  cv::randu(image, 0, type == CV_16UC1 ? 65535 : 255);
  return image;
}

TEST(ImageFileTest, ReadsTheSizeDepthAndChannelsOfEveryFormatFromTheHeader) {
  struct Case {
    std::string extension;
    cv::Mat image;
    std::string format;
    int bit_depth;
    int channels;
  };
  const std::vector<Case> cases = {
      {".png", Ramp(7, 13, CV_8UC1), "PNG", 8, 1},   {".png", Ramp(7, 13, CV_16UC1), "PNG", 16, 1},
      {".png", Ramp(7, 13, CV_8UC3), "PNG", 8, 3},   {".jpg", Ramp(7, 13, CV_8UC3), "JPEG", 8, 3},
      {".pgm", Ramp(7, 13, CV_8UC1), "PNM", 8, 1},   {".pgm", Ramp(7, 13, CV_16UC1), "PNM", 16, 1},
      {".ppm", Ramp(7, 13, CV_8UC3), "PNM", 8, 3},   {".bmp", Ramp(7, 13, CV_8UC3), "BMP", 8, 3},
  };
  for (const Case& c : cases) {
    const std::string path = Scratch("info" + c.extension);
    WriteBytes(path, Encode(c.extension, c.image));
    const ImageFileInfo info = ReadImageFileInfo(path);
    EXPECT_EQ(info.format, c.format) << c.extension;
    EXPECT_EQ(info.width, 13) << c.extension;
    EXPECT_EQ(info.height, 7) << c.extension;
    EXPECT_EQ(info.bit_depth, c.bit_depth) << c.extension << " " << c.image.depth();
    EXPECT_EQ(info.channels, c.channels) << c.extension;
    const cv::Mat decoded = ReadImageFile(path, cv::IMREAD_UNCHANGED);
    EXPECT_EQ(decoded.size(), c.image.size()) << c.extension;
  }
}

TEST(ImageFileTest, RefusesAHugeImageFromItsHeaderBeforeDecodingIt) {
  // A real 1 x 1 PNG whose IHDR claims 30000 x 30000 pixels: a few bytes that would decode to 2.7 GB.
  std::vector<uchar> bytes = Encode(".png", cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(9)));
  for (int offset : {16, 20}) {  // width, height: big-endian after the signature, length and "IHDR"
    bytes[offset] = 0x00;
    bytes[offset + 1] = 0x00;
    bytes[offset + 2] = 0x75;
    bytes[offset + 3] = 0x30;
  }
  const std::string path = Scratch("huge.png");
  WriteBytes(path, bytes);
  EXPECT_EQ(ReadImageFileInfo(path).width, 30000);
  CAIRN_EXPECT_THROWS_WITH(ReadImageFile(path, cv::IMREAD_COLOR), std::invalid_argument, path, "30000 x 30000",
                           "900000000 pixels", "limit of 67108864");
}

TEST(ImageFileTest, HonoursTheCallersPixelLimit) {
  const std::string path = Scratch("small.png");
  WriteBytes(path, Encode(".png", Ramp(20, 20, CV_8UC1)));
  EXPECT_EQ(ReadImageFile(path, cv::IMREAD_GRAYSCALE, 400).rows, 20);
  CAIRN_EXPECT_THROWS_WITH(ReadImageFile(path, cv::IMREAD_GRAYSCALE, 399), std::invalid_argument, "20 x 20",
                           "limit of 399");
  CAIRN_EXPECT_THROWS_WITH(ReadImageFile(path, cv::IMREAD_GRAYSCALE, 0), std::invalid_argument, "limit 0",
                           "positive");
}

// The message of `statement`'s std::runtime_error, which must be one line naming `path`.
std::string OneLineError(const std::string& path, int flags) {
  try {
    ReadImageFile(path, flags);
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("OpenCV"), std::string::npos) << message;
    EXPECT_EQ(message.find("libpng"), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "'" << path << "' was decoded";
  return "";
}

TEST(ImageFileTest, TruncatedOrDamagedFilesFailWithOneLineNamingThemBeforeAnyDecoderRuns) {
  const std::string png_path = Scratch("truncated.png");
  const std::vector<uchar> png = Encode(".png", Ramp(64, 64, CV_8UC3));
  WriteBytes(png_path, std::vector<uchar>(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(png.size() / 2)));
  EXPECT_NE(OneLineError(png_path, cv::IMREAD_COLOR).find("truncated"), std::string::npos);
  std::vector<uchar> damaged = png;
  damaged[damaged.size() / 2] ^= 0x5a;  // inside the IDAT chunk
  WriteBytes(png_path, damaged);
  EXPECT_NE(OneLineError(png_path, cv::IMREAD_COLOR).find("fails its CRC check"), std::string::npos);
  // Cut inside the header itself.
  WriteBytes(png_path, std::vector<uchar>(png.begin(), png.begin() + 14));
  CAIRN_EXPECT_THROWS_WITH(ReadImageFileInfo(png_path), std::runtime_error, png_path, "broken PNG header",
                           "ends early");

  const std::string jpeg_path = Scratch("truncated.jpg");
  const std::vector<uchar> jpeg = Encode(".jpg", Ramp(64, 64, CV_8UC3));
  WriteBytes(jpeg_path, std::vector<uchar>(jpeg.begin(), jpeg.end() - 40));
  EXPECT_NE(OneLineError(jpeg_path, cv::IMREAD_COLOR).find("no end-of-image marker"), std::string::npos);

  const std::string pgm_path = Scratch("truncated.pgm");
  const std::vector<uchar> pgm = Encode(".pgm", Ramp(64, 64, CV_8UC1));
  WriteBytes(pgm_path, std::vector<uchar>(pgm.begin(), pgm.end() - 100));
  EXPECT_NE(OneLineError(pgm_path, cv::IMREAD_GRAYSCALE).find("the raster needs 4096 bytes"), std::string::npos);

  const std::string bmp_path = Scratch("truncated.bmp");
  const std::vector<uchar> bmp = Encode(".bmp", Ramp(64, 64, CV_8UC3));
  WriteBytes(bmp_path, std::vector<uchar>(bmp.begin(), bmp.end() - 100));
  EXPECT_NE(OneLineError(bmp_path, cv::IMREAD_COLOR).find("the rows need"), std::string::npos);
}

TEST(ImageFileTest, NamesMissingFilesAndUnsupportedFormats) {
  CAIRN_EXPECT_THROWS_WITH(ReadImageFile(Scratch("missing.png"), cv::IMREAD_COLOR), std::runtime_error,
                           "missing.png", "no such readable file");
  const std::string text = Scratch("notes.txt");
  std::ofstream(text) << "not an image\n";
  CAIRN_EXPECT_THROWS_WITH(ReadImageFile(text, cv::IMREAD_COLOR), std::invalid_argument, "notes.txt",
                           "not a PNG, JPEG", "convert it to PNG");
  const std::string empty = Scratch("empty.png");
  std::ofstream(empty).flush();
  CAIRN_EXPECT_THROWS_WITH(ReadImageFile(empty, cv::IMREAD_COLOR), std::runtime_error, "empty.png", "empty");
}

TEST(ImageFileTest, RefusesAJpegThatClaimsAZeroHeight) {
  std::vector<uchar> bytes = Encode(".jpg", Ramp(8, 8, CV_8UC1));
  // The baseline frame header: FF C0, length (2), precision (1), then the height.
  for (std::size_t i = 0; i + 5 < bytes.size(); ++i) {
    if (bytes[i] == 0xFF && bytes[i + 1] == 0xC0) {
      bytes[i + 5] = 0;
      bytes[i + 6] = 0;
      break;
    }
  }
  const std::string path = Scratch("zero.jpg");
  WriteBytes(path, bytes);
  CAIRN_EXPECT_THROWS_WITH(ReadImageFileInfo(path), std::runtime_error, "broken JPEG header", "height 0");
}

}  // namespace
}  // namespace cairn::perception
