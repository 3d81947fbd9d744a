#include "ppp_core/gif_animation.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp {
namespace {

const std::vector<Rgb> kPalette = {{255, 255, 255}, {0, 0, 0}, {255, 0, 0}};

/// A 5x4 frame of index 0 with index `colour` at (x, y).
std::vector<std::uint8_t> frameWithDot(int x, int y, std::uint8_t colour) {
  std::vector<std::uint8_t> f(20, 0);
  f[static_cast<std::size_t>(y) * 5 + x] = colour;
  return f;
}

Rgb shownAt(const GifMovie& movie, int frame, int x, int y) {
  const std::uint8_t* p = &movie.frames[frame].rgb[(static_cast<std::size_t>(y) * movie.width + x) * 3];
  return Rgb{p[0], p[1], p[2]};
}

TEST(GifAnimationTest, ReadingBackShowsEveryFrameAsDrawn) {
  GifAnimation animation(5, 4, kPalette);
  animation.addFrame(frameWithDot(0, 0, 1), 10);
  animation.addFrame(frameWithDot(4, 3, 2), 20);  // the dot moves: the changed rectangle spans the whole picture
  animation.addFrame(frameWithDot(4, 3, 2), 30);  // nothing changes
  animation.addFrame(frameWithDot(3, 3, 1), 40);
  ASSERT_EQ(animation.frames(), 4);
  const GifMovie movie = decodeGif(animation.encode(), "test.gif");
  EXPECT_EQ(movie.width, 5);
  EXPECT_EQ(movie.height, 4);
  EXPECT_TRUE(movie.loops);
  ASSERT_EQ(movie.frames.size(), 4u);
  const int delays[] = {10, 20, 30, 40};
  const std::vector<std::uint8_t> frames[] = {frameWithDot(0, 0, 1), frameWithDot(4, 3, 2), frameWithDot(4, 3, 2),
                                              frameWithDot(3, 3, 1)};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(movie.frames[i].delay_centiseconds, delays[i]);
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 5; ++x) {
        EXPECT_EQ(shownAt(movie, i, x, y), kPalette[frames[i][static_cast<std::size_t>(y) * 5 + x]])
            << "frame " << i << " pixel (" << x << ", " << y << ")";
      }
    }
  }
}

TEST(GifAnimationTest, LoopsForeverAndAReaderTellsAnotherLoopCount) {
  GifAnimation animation(5, 4, kPalette);
  animation.addFrame(frameWithDot(0, 0, 1), 10);
  std::string bytes = animation.encode();
  EXPECT_TRUE(decodeGif(bytes, "loop.gif").loops);
  // The NETSCAPE2.0 block: the 11-byte name, then the sub-block {3, 1, count low, count high}.
  const std::size_t name = bytes.find("NETSCAPE2.0");
  ASSERT_NE(name, std::string::npos);
  ASSERT_EQ(bytes.substr(name + 11, 4), std::string("\x03\x01\x00\x00", 4));
  bytes[name + 13] = 1;  // play once more, not forever
  EXPECT_FALSE(decodeGif(bytes, "once.gif").loops);
}

TEST(GifAnimationTest, StoresOnlyTheChangedRectangle) {
  std::vector<std::uint8_t> big(200 * 200, 0);
  GifAnimation one(200, 200, kPalette);
  one.addFrame(big, 5);
  const std::size_t first = one.encode().size();
  big[100 * 200 + 100] = 1;
  one.addFrame(big, 5);
  // A second whole 200x200 frame would cost about as much as the first; one changed pixel costs a frame header.
  EXPECT_LT(one.encode().size() - first, 40u);
}

TEST(GifAnimationTest, TheSameFramesGiveTheSameBytes) {
  GifAnimation a(5, 4, kPalette);
  GifAnimation b(5, 4, kPalette);
  for (GifAnimation* g : {&a, &b}) {
    g->addFrame(frameWithDot(1, 1, 1), 7);
    g->addFrame(frameWithDot(2, 1, 2), 7);
  }
  EXPECT_EQ(a.encode(), b.encode());
  EXPECT_EQ(a.encode().substr(0, 6), "GIF89a");
}

TEST(GifAnimationTest, RejectsBadSizesPalettesFramesAndDelays) {
  EXPECT_THROW(GifAnimation(0, 4, kPalette), InvalidArgument);
  EXPECT_THROW(GifAnimation(5, kMaxPictureSide + 1, kPalette), InvalidArgument);
  EXPECT_THROW(GifAnimation(5, 4, {{0, 0, 0}}), InvalidArgument);
  EXPECT_THROW(GifAnimation(5, 4, std::vector<Rgb>(kMaxGifColours + 1)), InvalidArgument);
  GifAnimation g(5, 4, kPalette);
  EXPECT_THROW(g.encode(), Error);  // no frame
  EXPECT_THROW(g.addFrame(std::vector<std::uint8_t>(19, 0), 5), InvalidArgument);
  EXPECT_THROW(g.addFrame(frameWithDot(0, 0, 3), 5), InvalidArgument);  // index 3 of a 3-colour palette
  EXPECT_THROW(g.addFrame(frameWithDot(0, 0, 1), 0), InvalidArgument);
  EXPECT_THROW(g.addFrame(frameWithDot(0, 0, 1), 65536), InvalidArgument);
  try {
    g.addFrame(frameWithDot(0, 0, 3), 5);
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("palette index 3 outside the 3-colour palette"), std::string::npos) << e.what();
  }
}

TEST(GifAnimationTest, TheHeaderGivesThePictureSize) {
  GifAnimation animation(300, 4, kPalette);
  animation.addFrame(std::vector<std::uint8_t>(1200, 0), 10);
  int width = 0, height = 0;
  ASSERT_TRUE(gifScreenSize(animation.encode(), &width, &height));
  EXPECT_EQ(width, 300);
  EXPECT_EQ(height, 4);
  EXPECT_FALSE(gifScreenSize("GIF87a", &width, &height));
  EXPECT_EQ(width, 300);
}

TEST(GifAnimationTest, ReadingSomethingElseNamesTheSource) {
  try {
    decodeGif("\\x89PNG not a gif", "run.gif");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("run.gif: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace ppp
