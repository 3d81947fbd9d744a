#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/picture.hpp"

namespace ppp {

/// Most colours of a GIF palette.
constexpr int kMaxGifColours = 256;

/// An animated GIF built frame by frame from palette-indexed pixels and encoded by giflib. Each frame after the
/// first is stored as the smallest rectangle that changed since the previous one, drawn over it (GIF disposal
/// "do not dispose"), so frames that change a few cells cost a few hundred bytes. The animation loops forever.
class GifAnimation {
 public:
  /// An animation of `width` × `height` pixels (each in [1, kMaxPictureSide]) with `palette` (2 to
  /// kMaxGifColours colours). @throws InvalidArgument naming "gif size" or "gif palette".
  GifAnimation(int width, int height, std::vector<Rgb> palette);
  /// Appends a whole frame (width × height palette indices, row-major from the top-left) shown for
  /// `delay_centiseconds` (GIF's unit; in [1, 65535]). @throws InvalidArgument for a wrong size, an index
  /// outside the palette or a bad delay.
  void addFrame(const std::vector<std::uint8_t>& indices, int delay_centiseconds);
  /// Frames added so far.
  int frames() const { return static_cast<int>(frames_.size()); }
  /// The GIF file's bytes (GIF89a with a NETSCAPE2.0 loop block). @throws Error when there is no frame or
  /// giflib fails.
  std::string encode() const;

 private:
  struct Frame {
    int left, top, width, height;        // the changed rectangle
    int delay_centiseconds;
    std::vector<std::uint8_t> indices;  // its pixels, row-major
  };
  int width_;
  int height_;
  std::vector<Rgb> palette_;
  std::vector<std::uint8_t> last_;  // the previous whole frame
  std::vector<Frame> frames_;
};

/// Reads the picture size (the logical screen) from the header of GIF89a file bytes into `width` and `height`;
/// false, leaving them alone, when the bytes do not start with a GIF89a header.
bool gifScreenSize(const std::string& bytes, int* width, int* height);

/// One frame of a decoded GIF animation, as shown: the whole picture after drawing this frame's rectangle.
struct GifFrame {
  std::vector<std::uint8_t> rgb;  ///< width × height × 3 bytes, row-major from the top-left.
  int delay_centiseconds = 0;     ///< How long it is shown (0 when the file gives no delay).
};

/// A decoded GIF animation (giflib's reader), frames composited as a viewer shows them.
struct GifMovie {
  int width = 0;                ///< Picture columns.
  int height = 0;               ///< Picture rows.
  bool loops = false;           ///< True when a NETSCAPE2.0 block asks to loop forever.
  std::vector<GifFrame> frames; ///< In order.
};

/// Reads GIF file bytes back as whole frames (frames drawn over the previous one; disposal to background or
/// previous is not supported). Meant for checking what GifAnimation wrote.
/// @throws Error naming `source` when giflib cannot read the bytes, the picture is larger than kMaxPictureSide,
/// or a frame uses an unsupported feature.
GifMovie decodeGif(const std::string& bytes, const std::string& source);

}  // namespace ppp
