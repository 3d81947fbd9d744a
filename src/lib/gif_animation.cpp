#include "ppp_core/gif_animation.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include "ppp_core/error.hpp"

namespace ppp {

namespace {

/// giflib's message for an error code.
std::string gifErrorText(int code) {
  const char* text = GifErrorString(code);
  return text != nullptr ? text : "error " + std::to_string(code);
}

/// Where the encoder's bytes go, and whether appending them failed (no exception may cross giflib's C code).
struct ByteSink {
  std::string bytes;
  bool failed = false;
};

/// giflib's output callback: appends to the ByteSink in UserData; 0 (a write error to giflib) when it cannot.
int appendToSink(GifFileType* gif, const GifByteType* bytes, int count) {
  auto* sink = static_cast<ByteSink*>(gif->UserData);
  try {
    sink->bytes.append(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(count));
  } catch (...) {
    sink->failed = true;
    return 0;
  }
  return count;
}

/// giflib's input callback: reads from the ByteReader in UserData.
struct ByteReader {
  const std::string* bytes;
  std::size_t offset;
};
int readFromString(GifFileType* gif, GifByteType* out, int count) {
  auto* reader = static_cast<ByteReader*>(gif->UserData);
  const std::size_t n = std::min(static_cast<std::size_t>(count), reader->bytes->size() - reader->offset);
  std::copy_n(reader->bytes->data() + reader->offset, n, out);
  reader->offset += n;
  return static_cast<int>(n);
}

/// An open giflib encoder, closed when it goes out of scope (close() reports the closing's own error).
class GifWriter {
 public:
  explicit GifWriter(ByteSink* sink) {
    int error = 0;
    gif_ = EGifOpen(sink, &appendToSink, &error);
    if (gif_ == nullptr) throw Error("GIF encoding failed in EGifOpen: " + gifErrorText(error));
  }
  ~GifWriter() {
    int ignored = 0;
    if (gif_ != nullptr) EGifCloseFile(gif_, &ignored);
  }
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;
  GifFileType* get() const { return gif_; }
  /// Throws Error naming `call` unless `result` is GIF_OK.
  void check(int result, const char* call) const {
    if (result == GIF_ERROR) throw Error(std::string("GIF encoding failed in ") + call + ": " + gifErrorText(gif_->Error));
  }
  void close() {
    int error = 0;
    GifFileType* gif = gif_;
    gif_ = nullptr;
    if (EGifCloseFile(gif, &error) == GIF_ERROR) throw Error("GIF encoding failed in EGifCloseFile: " + gifErrorText(error));
  }

 private:
  GifFileType* gif_ = nullptr;
};

/// An open giflib decoder, closed when it goes out of scope.
class GifReader {
 public:
  GifReader(ByteReader* reader, const std::string& source) {
    int error = 0;
    gif_ = DGifOpen(reader, &readFromString, &error);
    if (gif_ == nullptr) throw Error(source + ": not a GIF file (" + gifErrorText(error) + ")");
  }
  ~GifReader() {
    int ignored = 0;
    DGifCloseFile(gif_, &ignored);
  }
  GifReader(const GifReader&) = delete;
  GifReader& operator=(const GifReader&) = delete;
  GifFileType* get() const { return gif_; }

 private:
  GifFileType* gif_;
};

/// Bits per palette index that hold `colours` (GIF palettes have 2^bits entries).
int paletteBits(int colours) {
  int bits = 1;
  while ((1 << bits) < colours) ++bits;
  return bits;
}

/// True when an image's extension blocks hold a NETSCAPE2.0 block asking to loop forever (loop count 0).
bool loopsForever(const SavedImage& image) {
  for (int e = 0; e + 1 < image.ExtensionBlockCount; ++e) {
    const ExtensionBlock& block = image.ExtensionBlocks[e];
    const ExtensionBlock& data = image.ExtensionBlocks[e + 1];
    if (block.Function == APPLICATION_EXT_FUNC_CODE && block.ByteCount == 11 &&
        std::memcmp(block.Bytes, "NETSCAPE2.0", 11) == 0 && data.Function == CONTINUE_EXT_FUNC_CODE &&
        data.ByteCount == 3 && data.Bytes[0] == 1 && (data.Bytes[1] | data.Bytes[2] << 8) == 0) {
      return true;
    }
  }
  return false;
}

}  // namespace

GifAnimation::GifAnimation(int width, int height, std::vector<Rgb> palette)
    : width_(width), height_(height), palette_(std::move(palette)) {
  if (width < 1 || height < 1 || width > kMaxPictureSide || height > kMaxPictureSide) {
    throw InvalidArgument("gif size", "expected width and height in [1, " + std::to_string(kMaxPictureSide) +
                                          "], got " + std::to_string(width) + "x" + std::to_string(height));
  }
  if (palette_.size() < 2 || palette_.size() > static_cast<std::size_t>(kMaxGifColours)) {
    throw InvalidArgument("gif palette", "expected 2 to " + std::to_string(kMaxGifColours) + " colours, got " +
                                             std::to_string(palette_.size()));
  }
}

void GifAnimation::addFrame(const std::vector<std::uint8_t>& indices, int delay_centiseconds) {
  const std::size_t expected = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  if (indices.size() != expected) {
    throw InvalidArgument("gif frame", "expected " + std::to_string(expected) + " palette indices, got " +
                                           std::to_string(indices.size()));
  }
  if (delay_centiseconds < 1 || delay_centiseconds > 65535) {
    throw InvalidArgument("gif delay", "expected centiseconds in [1, 65535], got " + std::to_string(delay_centiseconds));
  }
  const std::uint8_t largest = *std::max_element(indices.begin(), indices.end());
  if (largest >= palette_.size()) {
    throw InvalidArgument("gif frame", "palette index " + std::to_string(largest) + " outside the " +
                                           std::to_string(palette_.size()) + "-colour palette");
  }
  // The rectangle that changed; a whole first frame; one pixel when nothing changed (the frame still counts).
  int left = 0, top = 0, right = width_ - 1, bottom = height_ - 1;
  if (!last_.empty()) {
    left = width_, top = height_, right = -1, bottom = -1;
    for (int y = 0; y < height_; ++y) {
      const std::uint8_t* now = indices.data() + static_cast<std::size_t>(y) * width_;
      const std::uint8_t* before = last_.data() + static_cast<std::size_t>(y) * width_;
      if (std::memcmp(now, before, static_cast<std::size_t>(width_)) == 0) continue;
      int first = 0, last = width_ - 1;
      while (now[first] == before[first]) ++first;
      while (now[last] == before[last]) --last;
      left = std::min(left, first), right = std::max(right, last);
      top = std::min(top, y), bottom = y;
    }
    if (right < 0) left = top = right = bottom = 0;
  }
  Frame frame{left, top, right - left + 1, bottom - top + 1, delay_centiseconds, {}};
  frame.indices.reserve(static_cast<std::size_t>(frame.width) * frame.height);
  for (int y = top; y <= bottom; ++y) {
    const auto row = indices.begin() + static_cast<std::ptrdiff_t>(y) * width_;
    frame.indices.insert(frame.indices.end(), row + left, row + right + 1);
  }
  frames_.push_back(std::move(frame));
  last_ = indices;
}

std::string GifAnimation::encode() const {
  if (frames_.empty()) throw Error("GIF encoding: the animation has no frame");
  ByteSink sink;
  GifWriter writer(&sink);
  GifFileType* gif = writer.get();
  const int bits = paletteBits(static_cast<int>(palette_.size()));
  std::vector<GifColorType> colours(static_cast<std::size_t>(1) << bits, GifColorType{0, 0, 0});
  for (std::size_t i = 0; i < palette_.size(); ++i) colours[i] = GifColorType{palette_[i].r, palette_[i].g, palette_[i].b};
  ColorMapObject* map = GifMakeMapObject(static_cast<int>(colours.size()), colours.data());
  if (map == nullptr) throw Error("GIF encoding failed in GifMakeMapObject");
  EGifSetGifVersion(gif, true);  // GIF89a: delays and the loop block are extensions
  const int described = EGifPutScreenDesc(gif, width_, height_, bits, 0, map);
  GifFreeMapObject(map);
  writer.check(described, "EGifPutScreenDesc");
  // NETSCAPE2.0 application block: loop count 0 = forever.
  const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  const GifByteType loop[] = {1, 0, 0};
  writer.check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), "the loop block");
  writer.check(EGifPutExtensionBlock(gif, sizeof netscape, netscape), "the loop block");
  writer.check(EGifPutExtensionBlock(gif, sizeof loop, loop), "the loop block");
  writer.check(EGifPutExtensionTrailer(gif), "the loop block");
  std::vector<GifPixelType> line;  // EGifPutLine masks the line it is given in place, so it gets a copy
  for (const Frame& frame : frames_) {
    GraphicsControlBlock control{DISPOSE_DO_NOT, false, frame.delay_centiseconds, NO_TRANSPARENT_COLOR};
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&control, extension);
    writer.check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension), "EGifPutExtension");
    writer.check(EGifPutImageDesc(gif, frame.left, frame.top, frame.width, frame.height, false, nullptr),
                 "EGifPutImageDesc");
    for (int y = 0; y < frame.height; ++y) {
      const auto row = frame.indices.begin() + static_cast<std::ptrdiff_t>(y) * frame.width;
      line.assign(row, row + frame.width);
      writer.check(EGifPutLine(gif, line.data(), frame.width), "EGifPutLine");
    }
  }
  writer.close();
  if (sink.failed) throw Error("GIF encoding: out of memory for the file's bytes");
  return std::move(sink.bytes);
}

bool gifScreenSize(const std::string& bytes, int* width, int* height) {
  if (bytes.size() < 10 || bytes.compare(0, 6, "GIF89a") != 0) return false;
  const auto byte = [&](std::size_t k) { return static_cast<int>(static_cast<unsigned char>(bytes[k])); };
  *width = byte(6) | byte(7) << 8;  // little-endian
  *height = byte(8) | byte(9) << 8;
  return true;
}

GifMovie decodeGif(const std::string& bytes, const std::string& source) {
  ByteReader input{&bytes, 0};
  GifReader reader(&input, source);
  GifFileType* gif = reader.get();
  if (DGifSlurp(gif) == GIF_ERROR) throw Error(source + ": cannot read the GIF (" + gifErrorText(gif->Error) + ")");
  GifMovie movie;
  movie.width = gif->SWidth;
  movie.height = gif->SHeight;
  if (movie.width < 1 || movie.height < 1 || movie.width > kMaxPictureSide || movie.height > kMaxPictureSide) {
    throw Error(source + ": a " + std::to_string(movie.width) + "x" + std::to_string(movie.height) +
                " picture; this reader takes sides in [1, " + std::to_string(kMaxPictureSide) + "]");
  }
  std::vector<std::uint8_t> shown(static_cast<std::size_t>(movie.width) * movie.height * 3, 0);
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& image = gif->SavedImages[i];
    movie.loops = movie.loops || loopsForever(image);
    GraphicsControlBlock control{DISPOSAL_UNSPECIFIED, false, 0, NO_TRANSPARENT_COLOR};
    DGifSavedExtensionToGCB(gif, i, &control);
    const GifImageDesc& d = image.ImageDesc;
    const ColorMapObject* map = d.ColorMap != nullptr ? d.ColorMap : gif->SColorMap;
    if (map == nullptr || d.Interlace || control.TransparentColor != NO_TRANSPARENT_COLOR ||
        control.DisposalMode == DISPOSE_BACKGROUND || control.DisposalMode == DISPOSE_PREVIOUS ||
        d.Left < 0 || d.Top < 0 || d.Left + d.Width > movie.width || d.Top + d.Height > movie.height) {
      throw Error(source + ": frame " + std::to_string(i) + " uses a GIF feature this reader does not support");
    }
    for (int y = 0; y < d.Height; ++y) {
      for (int x = 0; x < d.Width; ++x) {
        const int index = image.RasterBits[static_cast<std::size_t>(y) * d.Width + x];
        if (index >= map->ColorCount) {
          throw Error(source + ": frame " + std::to_string(i) + " has a palette index outside its palette");
        }
        const GifColorType c = map->Colors[index];
        std::uint8_t* p = &shown[(static_cast<std::size_t>(d.Top + y) * movie.width + d.Left + x) * 3];
        p[0] = c.Red, p[1] = c.Green, p[2] = c.Blue;
      }
    }
    movie.frames.push_back(GifFrame{shown, control.DelayTime});
  }
  return movie;
}

}  // namespace ppp
