#include "ppp_core/gif_animation.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include "ppp_core/error.hpp"

namespace ppp {

namespace {

/// giflib's output callback: appends to the std::string in UserData.
int appendToString(GifFileType* gif, const GifByteType* bytes, int count) {
  static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(count));
  return count;
}

/// Bits per palette index that hold `colours` (GIF palettes have 2^bits entries).
int paletteBits(int colours) {
  int bits = 1;
  while ((1 << bits) < colours) ++bits;
  return bits;
}

/// Closes `gif` and throws Error naming the giflib call that failed.
[[noreturn]] void failGif(GifFileType* gif, const char* call) {
  const int code = gif->Error;
  int ignored = 0;
  EGifCloseFile(gif, &ignored);
  const char* text = GifErrorString(code);
  throw Error(std::string("GIF encoding failed in ") + call + ": " + (text != nullptr ? text : "unknown error"));
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
  std::string out;
  int error = 0;
  GifFileType* gif = EGifOpen(&out, &appendToString, &error);
  if (gif == nullptr) throw Error(std::string("GIF encoding failed in EGifOpen: ") + GifErrorString(error));
  const int bits = paletteBits(static_cast<int>(palette_.size()));
  std::vector<GifColorType> colours(static_cast<std::size_t>(1) << bits, GifColorType{0, 0, 0});
  for (std::size_t i = 0; i < palette_.size(); ++i) colours[i] = GifColorType{palette_[i].r, palette_[i].g, palette_[i].b};
  ColorMapObject* map = GifMakeMapObject(static_cast<int>(colours.size()), colours.data());
  if (map == nullptr) failGif(gif, "GifMakeMapObject");
  EGifSetGifVersion(gif, true);  // GIF89a: delays and the loop block are extensions
  const int described = EGifPutScreenDesc(gif, width_, height_, bits, 0, map);
  GifFreeMapObject(map);
  if (described == GIF_ERROR) failGif(gif, "EGifPutScreenDesc");
  // NETSCAPE2.0 application block: loop count 0 = forever.
  const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  const GifByteType loop[] = {1, 0, 0};
  if (EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif, sizeof netscape, netscape) == GIF_ERROR ||
      EGifPutExtensionBlock(gif, sizeof loop, loop) == GIF_ERROR || EGifPutExtensionTrailer(gif) == GIF_ERROR) {
    failGif(gif, "the loop block");
  }
  for (const Frame& frame : frames_) {
    GraphicsControlBlock control{DISPOSE_DO_NOT, false, frame.delay_centiseconds, NO_TRANSPARENT_COLOR};
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&control, extension);
    if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) == GIF_ERROR) {
      failGif(gif, "EGifPutExtension");
    }
    if (EGifPutImageDesc(gif, frame.left, frame.top, frame.width, frame.height, false, nullptr) == GIF_ERROR) {
      failGif(gif, "EGifPutImageDesc");
    }
    for (int y = 0; y < frame.height; ++y) {
      // giflib's API takes non-const lines; it only reads them.
      auto* line = const_cast<GifPixelType*>(frame.indices.data() + static_cast<std::size_t>(y) * frame.width);
      if (EGifPutLine(gif, line, frame.width) == GIF_ERROR) failGif(gif, "EGifPutLine");
    }
  }
  if (EGifCloseFile(gif, &error) == GIF_ERROR) {
    throw Error(std::string("GIF encoding failed in EGifCloseFile: ") + GifErrorString(error));
  }
  return out;
}

GifMovie decodeGif(const std::string& bytes, const std::string& source) {
  ByteReader reader{&bytes, 0};
  int error = 0;
  GifFileType* gif = DGifOpen(&reader, &readFromString, &error);
  if (gif == nullptr) throw Error(source + ": not a GIF file (" + GifErrorString(error) + ")");
  if (DGifSlurp(gif) == GIF_ERROR) {
    const std::string text = GifErrorString(gif->Error);
    DGifCloseFile(gif, &error);
    throw Error(source + ": cannot read the GIF (" + text + ")");
  }
  GifMovie movie;
  movie.width = gif->SWidth;
  movie.height = gif->SHeight;
  std::vector<std::uint8_t> shown(static_cast<std::size_t>(movie.width) * movie.height * 3, 0);
  std::string problem;
  for (int i = 0; i < gif->ImageCount && problem.empty(); ++i) {
    const SavedImage& image = gif->SavedImages[i];
    for (int e = 0; e < image.ExtensionBlockCount; ++e) {
      const ExtensionBlock& block = image.ExtensionBlocks[e];
      if (block.Function == APPLICATION_EXT_FUNC_CODE && block.ByteCount == 11 &&
          std::string(reinterpret_cast<const char*>(block.Bytes), 11) == "NETSCAPE2.0") {
        movie.loops = true;
      }
    }
    GraphicsControlBlock control{DISPOSAL_UNSPECIFIED, false, 0, NO_TRANSPARENT_COLOR};
    DGifSavedExtensionToGCB(gif, i, &control);
    const GifImageDesc& d = image.ImageDesc;
    const ColorMapObject* map = d.ColorMap != nullptr ? d.ColorMap : gif->SColorMap;
    if (map == nullptr || d.Interlace || control.TransparentColor != NO_TRANSPARENT_COLOR ||
        control.DisposalMode == DISPOSE_BACKGROUND || control.DisposalMode == DISPOSE_PREVIOUS ||
        d.Left < 0 || d.Top < 0 || d.Left + d.Width > movie.width || d.Top + d.Height > movie.height) {
      problem = "frame " + std::to_string(i) + " uses a GIF feature this reader does not support";
      break;
    }
    for (int y = 0; y < d.Height; ++y) {
      for (int x = 0; x < d.Width; ++x) {
        const int index = image.RasterBits[static_cast<std::size_t>(y) * d.Width + x];
        if (index >= map->ColorCount) {
          problem = "frame " + std::to_string(i) + " has a palette index outside its palette";
          break;
        }
        const GifColorType c = map->Colors[index];
        std::uint8_t* p = &shown[(static_cast<std::size_t>(d.Top + y) * movie.width + d.Left + x) * 3];
        p[0] = c.Red, p[1] = c.Green, p[2] = c.Blue;
      }
    }
    movie.frames.push_back(GifFrame{shown, control.DelayTime});
  }
  DGifCloseFile(gif, &error);
  if (!problem.empty()) throw Error(source + ": " + problem);
  return movie;
}

}  // namespace ppp
