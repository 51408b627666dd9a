// CPU-side images: PNG files round trip exactly, image comparison gives the figures computed by hand, and
// the procedural bark is deterministic, tileable, elongated along v and equal to the committed assets.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>

#include "common/atomic_file.hpp"
#include "image/bark_texture.hpp"
#include "image/image_compare.hpp"
#include "image/leaf_atlas.hpp"
#include "image/plot.hpp"
#include "image/png_io.hpp"
#include "test_support.hpp"

using namespace arbor;
using Catch::Matchers::Contains;

namespace {

Image blank(int width, int height, std::uint8_t value = 0) {
  return Image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4, value)};
}

// Random bytes; `opaque` sets alpha to 255 and `grey` copies R into G and B.
Image noiseImage(int width, int height, std::uint32_t seed, bool opaque, bool grey) {
  std::mt19937 random(seed);
  Image image = blank(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 4; ++c) image.rgba[i + c] = static_cast<std::uint8_t>(random() & 0xffu);
    if (grey) image.rgba[i + 1] = image.rgba[i + 2] = image.rgba[i];
    if (opaque) image.rgba[i + 3] = 255;
  }
  return image;
}

int pngColourType(const std::string& png) {
  REQUIRE(png.size() > 25);
  return static_cast<unsigned char>(png[25]);  // the IHDR chunk's colour type byte
}

int channel(const Image& image, int x, int y, int c) {
  return image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4 + c];
}

// Mean |difference| over RGB between column x0 and column x1 (or rows, when `rows`).
double lineDifference(const Image& image, int a, int b, bool rows) {
  const int length = rows ? image.width : image.height;
  double sum = 0.0;
  for (int i = 0; i < length; ++i) {
    for (int c = 0; c < 3; ++c) {
      sum += rows ? std::abs(channel(image, i, a, c) - channel(image, i, b, c))
                  : std::abs(channel(image, a, i, c) - channel(image, b, i, c));
    }
  }
  return sum / (3.0 * length);
}

// The average difference between neighbouring interior columns (or rows).
double interiorNeighbourDifference(const Image& image, bool rows) {
  const int count = rows ? image.height : image.width;
  double sum = 0.0;
  for (int i = 0; i + 1 < count; ++i) sum += lineDifference(image, i, i + 1, rows);
  return sum / (count - 1);
}

// The columns [0, width) of an image: a window that is not a whole period, so it does not tile.
Image leftPart(const Image& image, int width) {
  Image part = blank(width, image.height);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 4; ++c) part.rgba[(static_cast<std::size_t>(y) * width + x) * 4 + c] =
                                       static_cast<std::uint8_t>(channel(image, x, y, c));
    }
  }
  return part;
}

const BarkTextures& bark512() {
  static const BarkTextures maps = makeBarkTextures(512, 1);
  return maps;
}

}  // namespace

TEST_CASE("PNG write and read give back the same bytes", "[image]") {
  struct Case {
    const char* name;
    Image image;
    int colourType;  // what encodePng should choose: 0 grey, 2 RGB, 6 RGBA
  };
  const std::vector<Case> cases = {{"rgba", noiseImage(37, 23, 1, false, false), 6},
                                   {"rgb", noiseImage(16, 9, 2, true, false), 2},
                                   {"grey", noiseImage(5, 31, 3, true, true), 0},
                                   {"grey with alpha", noiseImage(8, 8, 4, false, true), 6},
                                   {"one pixel", noiseImage(1, 1, 5, false, false), 6}};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    INFO(c.name);
    const std::string png = encodePng(c.image);
    CHECK(pngColourType(png) == c.colourType);
    const Image fromMemory = decodePng(png, c.name);
    CHECK(fromMemory.width == c.image.width);
    CHECK(fromMemory.height == c.image.height);
    CHECK(fromMemory.rgba == c.image.rgba);

    const std::string path = test::tempPath("round-trip-" + std::to_string(k) + ".png");
    writePng(path, c.image);
    CHECK(readFile(path) == png);
    const Image fromFile = readPng(path);
    CHECK(fromFile.width == c.image.width);
    CHECK(fromFile.height == c.image.height);
    CHECK(fromFile.rgba == c.image.rgba);
  }
}

TEST_CASE("PNG errors name the file and the reason", "[image]") {
  const std::string missing = test::tempPath("no-such-file.png");
  CHECK_THROWS_WITH(readPng(missing), Contains(missing) && Contains("cannot be opened"));
  const std::string text = test::tempPath("not-a-png.png");
  writeFileAtomically(text, "this is not a PNG file");
  CHECK_THROWS_WITH(readPng(text), Contains(text) && Contains("cannot be read as PNG ("));
  Image wrongSize = blank(4, 4);
  wrongSize.rgba.pop_back();
  CHECK_THROWS_AS(encodePng(wrongSize), std::invalid_argument);
  CHECK_THROWS_AS(encodePng(Image{}), std::invalid_argument);
  CHECK_THROWS_AS(writePng(test::tempPath("no-such-dir/x.png"), blank(2, 2)), std::runtime_error);
}

TEST_CASE("identical images differ by nothing", "[image]") {
  const Image a = noiseImage(13, 7, 6, false, false);
  const ImageDifference d = compareImages(a, a, 0);
  CHECK(d.maxChannelDifference == 0);
  CHECK(std::isinf(d.psnr));
  CHECK(d.psnr > 0);
  CHECK(d.pixelsOverThreshold == 0);
  CHECK(d.meanAbsoluteDifference == 0.0);
}

TEST_CASE("one channel of one pixel off by 10 gives the figures computed by hand", "[image]") {
  const Image a = blank(4, 4, 100);
  Image b = a;
  b.rgba[(2 * 4 + 1) * 4 + 0] = 110;  // red of pixel (1, 2)
  b.rgba[(0 * 4 + 3) * 4 + 3] = 0;    // alpha is ignored
  const ImageDifference d = compareImages(a, b, 5);
  CHECK(d.maxChannelDifference == 10);
  // 48 RGB samples, one off by 10: MSE = 100 / 48, PSNR = 10 log10(255^2 * 48 / 100).
  CHECK(d.psnr == Approx(44.94321598243498).epsilon(1e-12));
  CHECK(d.pixelsOverThreshold == 1);
  CHECK(d.meanAbsoluteDifference == Approx(10.0 / 48.0).epsilon(1e-12));
  CHECK(compareImages(a, b, 10).pixelsOverThreshold == 0);  // "exceeds": a difference equal to it is not counted

  Image c = a;  // the same pixel off by 10 in all three channels
  for (int k = 0; k < 3; ++k) c.rgba[(2 * 4 + 1) * 4 + k] = 90;
  const ImageDifference e = compareImages(a, c, 5);
  CHECK(e.maxChannelDifference == 10);
  CHECK(e.psnr == Approx(40.17200343523835).epsilon(1e-12));
  CHECK(e.pixelsOverThreshold == 1);
}

TEST_CASE("images of different sizes are not compared", "[image]") {
  CHECK_THROWS_AS(compareImages(blank(4, 4), blank(4, 5), 0), std::invalid_argument);
  CHECK_THROWS_AS(compareImages(blank(4, 4), blank(2, 8), 0), std::invalid_argument);
  CHECK_THROWS_AS(differenceImage(blank(3, 3), blank(4, 3)), std::invalid_argument);
}

TEST_CASE("the difference image is black where the images agree and visible where they do not", "[image]") {
  const Image a = blank(3, 2, 50);
  Image b = a;
  b.rgba[(1 * 3 + 2) * 4 + 1] = 51;   // green off by one at (2, 1)
  b.rgba[(0 * 3 + 0) * 4 + 2] = 250;  // blue off by 200 at (0, 0)
  const Image d = differenceImage(a, b);
  REQUIRE(d.width == 3);
  REQUIRE(d.height == 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(channel(d, x, y, 3) == 255);
      const bool changedGreen = x == 2 && y == 1, changedBlue = x == 0 && y == 0;
      CHECK(channel(d, x, y, 0) == 0);
      CHECK((channel(d, x, y, 1) >= 32) == changedGreen);
      CHECK((channel(d, x, y, 2) == 255) == changedBlue);
    }
  }
}

TEST_CASE("bark textures are deterministic and differ between seeds", "[image][bark]") {
  const BarkTextures again = makeBarkTextures(512, 1);
  CHECK(again.color.rgba == bark512().color.rgba);
  CHECK(again.height.rgba == bark512().height.rgba);
  const BarkTextures other = makeBarkTextures(512, 2);
  CHECK(compareImages(other.height, bark512().height, 0).meanAbsoluteDifference > 20.0);
  CHECK(compareImages(other.color, bark512().color, 0).meanAbsoluteDifference > 5.0);
  CHECK_THROWS_AS(makeBarkTextures(0, 1), std::invalid_argument);
}

TEST_CASE("bark textures tile in u and v", "[image][bark]") {
  for (int size : {64, 512}) {
    const BarkTextures maps = size == 512 ? bark512() : makeBarkTextures(size, 7);
    for (const Image* image : {&maps.color, &maps.height}) {
      for (bool rows : {false, true}) {
        INFO("size " << size << (image == &maps.color ? " colour" : " height") << (rows ? " rows" : " columns"));
        const int last = (rows ? image->height : image->width) - 1;
        const double seam = lineDifference(*image, last, 0, rows), interior = interiorNeighbourDifference(*image, rows);
        INFO("seam " << seam << ", interior " << interior);
        CHECK(interior > 0.5);
        CHECK(seam < 1.5 * interior);
      }
    }
  }
  // The check has teeth: a window that is not a whole period has a visible seam.
  const Image cut = leftPart(bark512().height, 300);
  CHECK(lineDifference(cut, 299, 0, false) > 3.0 * interiorNeighbourDifference(cut, false));
}

TEST_CASE("the bark height map is grey, centred on 128 and elongated along v", "[image][bark]") {
  const Image& h = bark512().height;
  double sum = 0.0, alongU = 0.0, alongV = 0.0;
  double dark = 0.0, light = 0.0;
  for (int y = 0; y < h.height; ++y) {
    for (int x = 0; x < h.width; ++x) {
      const int value = channel(h, x, y, 0);
      REQUIRE(channel(h, x, y, 1) == value);
      REQUIRE(channel(h, x, y, 2) == value);
      REQUIRE(channel(h, x, y, 3) == 255);
      sum += value;
      dark += value < 48 ? 1.0 : 0.0;
      light += value > 192 ? 1.0 : 0.0;
      alongU += std::abs(channel(h, (x + 1) % h.width, y, 0) - value);
      alongV += std::abs(channel(h, x, (y + 1) % h.height, 0) - value);
    }
  }
  const double pixels = static_cast<double>(h.width) * h.height;
  INFO("mean " << sum / pixels << ", along u " << alongU / pixels << ", along v " << alongV / pixels);
  CHECK(std::abs(sum / pixels - 128.0) < 8.0);
  CHECK(dark / pixels > 0.02);   // fissures exist
  CHECK(light / pixels > 0.02);  // and plate tops
  CHECK(alongV < 0.6 * alongU);  // ridges run along v
}

TEST_CASE("the bark colour map is brown-grey and darker in the fissures", "[image][bark]") {
  const Image& c = bark512().color;
  const Image& h = bark512().height;
  double r = 0.0, g = 0.0, b = 0.0, fissure = 0.0, plate = 0.0, fissures = 0.0, plates = 0.0;
  for (std::size_t i = 0; i < c.rgba.size(); i += 4) {
    r += c.rgba[i];
    g += c.rgba[i + 1];
    b += c.rgba[i + 2];
    const double luminance = 0.2126 * c.rgba[i] + 0.7152 * c.rgba[i + 1] + 0.0722 * c.rgba[i + 2];
    if (h.rgba[i] < 64) fissure += luminance, fissures += 1.0;
    if (h.rgba[i] > 160) plate += luminance, plates += 1.0;
  }
  REQUIRE(fissures > 0);
  REQUIRE(plates > 0);
  CHECK(r > g);
  CHECK(g > b);
  CHECK(fissure / fissures < 0.5 * plate / plates);
  const double pixels = static_cast<double>(c.rgba.size() / 4);
  CHECK(r / pixels > 50.0);   // neither black
  CHECK(r / pixels < 180.0);  // nor pale
}

TEST_CASE("the committed bark textures are what the generator makes", "[image][bark]") {
  // assets/textures/ is `arbor textures --size 512 --seed 1 --out assets/textures`; regenerate it after any change.
  const std::filesystem::path dir = std::filesystem::path(ARBOR_ASSET_DIR) / "textures";
  const Image color = readPng((dir / "bark_color.png").string());
  const Image height = readPng((dir / "bark_height.png").string());
  CHECK(std::filesystem::file_size(dir / "bark_color.png") < 1000000);
  CHECK(std::filesystem::file_size(dir / "bark_height.png") < 1000000);
  CHECK(color.width == 512);
  CHECK(color.height == 512);
  CHECK(color.rgba == bark512().color.rgba);
  CHECK(height.rgba == bark512().height.rgba);
  CHECK(readPng((dir / "bark_normal.png").string()).rgba == bark512().normal.rgba);
}

TEST_CASE("the normal map leans away from rising height, green up the image, blue out", "[image][bark]") {
  // Height rising to the right (+u) and towards the image's top (against v): the normal leans left and down.
  Image height;
  height.width = height.height = 8;
  height.rgba.resize(8 * 8 * 4, 255);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 3; ++c) height.rgba[static_cast<std::size_t>((y * 8 + x) * 4 + c)] = static_cast<std::uint8_t>(100 + 4 * x - 3 * y);
  const Image n = normalMapFromHeight(height, 255.0 / 4.0);  // one grey level per texel of relief... times 255/4
  const std::size_t middle = static_cast<std::size_t>((4 * 8 + 4) * 4);
  CHECK(n.rgba[middle + 0] < 128);  // leans against +x
  CHECK(n.rgba[middle + 1] < 128);  // height rises up the image: leans down
  CHECK(n.rgba[middle + 2] > 128);
  CHECK(n.rgba[middle + 3] == 255);
  // A flat height map is (128, 128, 255) everywhere: straight out.
  Image flat = height;
  std::fill(flat.rgba.begin(), flat.rgba.end(), std::uint8_t{90});
  const Image straight = normalMapFromHeight(flat, 6.0);
  for (std::size_t i = 0; i < straight.rgba.size(); i += 4) {
    CHECK(straight.rgba[i] == 128);
    CHECK(straight.rgba[i + 1] == 128);
    CHECK(straight.rgba[i + 2] == 255);
  }
}

namespace {

const Image& atlas512() {
  static const Image atlas = makeLeafAtlas(512, 1);
  return atlas;
}

}  // namespace

TEST_CASE("the leaf atlas holds four different green cutouts, base at the bottom of each cell", "[image][leaves]") {
  const Image& a = atlas512();
  REQUIRE(a.width == 512);
  const int cell = 256;
  std::vector<std::vector<std::uint8_t>> alphas(kLeafAtlasCells);
  for (int k = 0; k < kLeafAtlasCells; ++k) {
    INFO("cell " << k);
    const int x0 = (k % 2) * cell, y0 = (k / 2) * cell;
    double covered = 0.0, r = 0.0, g = 0.0, b = 0.0, bottomCentre = 0.0;
    for (int y = y0; y < y0 + cell; ++y) {
      for (int x = x0; x < x0 + cell; ++x) {
        const std::uint8_t* p = &a.rgba[(static_cast<std::size_t>(y) * 512 + x) * 4];
        alphas[static_cast<std::size_t>(k)].push_back(p[3]);
        if (p[3] < 128) continue;
        covered += 1.0, r += p[0], g += p[1], b += p[2];
        if (y >= y0 + cell - 8 && std::abs(x - (x0 + cell / 2)) <= 4) bottomCentre += 1.0;
      }
    }
    const double share = covered / (cell * cell);
    CHECK(share > 0.02);  // a leaf, not a speck
    CHECK(share < 0.7);   // and not a square
    CHECK(g > r);         // green
    CHECK(r > b);
    CHECK(bottomCentre > 0.0);  // the stalk meets the cell's bottom centre, where the leaf is attached
    // The cell's top corners are transparent, so neighbouring cells do not bleed into each other's quads.
    CHECK(a.rgba[(static_cast<std::size_t>(y0) * 512 + x0) * 4 + 3] == 0);
    CHECK(a.rgba[(static_cast<std::size_t>(y0) * 512 + x0 + cell - 1) * 4 + 3] == 0);
  }
  for (int i = 0; i < kLeafAtlasCells; ++i) {
    for (int j = i + 1; j < kLeafAtlasCells; ++j) CHECK(alphas[static_cast<std::size_t>(i)] != alphas[static_cast<std::size_t>(j)]);
  }
}

TEST_CASE("the leaf atlas is deterministic and the committed copy is what the generator makes", "[image][leaves]") {
  CHECK(makeLeafAtlas(64, 1).rgba == makeLeafAtlas(64, 1).rgba);
  CHECK_THROWS_AS(makeLeafAtlas(100, 1), std::invalid_argument);
  const Image committed = readPng((std::filesystem::path(ARBOR_ASSET_DIR) / "textures" / "leaf_atlas.png").string());
  CHECK(committed.rgba == atlas512().rgba);
}

TEST_CASE("a plot draws each series in its colour along a rising line, with a legend, panels side by side", "[image][plot]") {
  PlotPanel panel{"Title", "factor", "ms", {}};
  panel.series.push_back({"rising", {1, 2, 4, 8}, {1, 10, 100, 1000}, {200, 0, 0}});
  panel.series.push_back({"flat", {1, 8}, {5, 5}, {0, 0, 200}});
  panel.series.push_back({"nothing", {0, -1}, {1, 2}, {0, 200, 0}});  // not on a log axis: left out
  const Image image = plotPanels({panel, panel}, 300, 200);
  REQUIRE(image.width == 600);
  REQUIRE(image.height == 200);
  const auto count = [&](std::array<std::uint8_t, 3> c, int x0, int x1) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::size_t i = 4 * (static_cast<std::size_t>(y) * 600 + static_cast<std::size_t>(x));
        n += image.rgba[i] == c[0] && image.rgba[i + 1] == c[1] && image.rgba[i + 2] == c[2] ? 1 : 0;
      }
    return n;
  };
  CHECK(count({200, 0, 0}, 0, 300) > 200);
  CHECK(count({0, 0, 200}, 0, 300) > 200);
  CHECK(count({0, 200, 0}, 0, 300) > 0);   // only its legend swatch
  CHECK(count({0, 200, 0}, 0, 300) < 100);
  CHECK(count({200, 0, 0}, 0, 300) == count({200, 0, 0}, 300, 600));  // the second panel is the same
  // The rising series climbs from the bottom left to the top right: its red pixels on the left half are
  // lower in the picture than those on the right half.
  double leftY = 0, rightY = 0, left = 0, right = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 300; ++x) {
      const std::size_t i = 4 * (static_cast<std::size_t>(y) * 600 + static_cast<std::size_t>(x));
      if (image.rgba[i] != 200 || image.rgba[i + 1] != 0 || x > 200) continue;  // the legend sits at the right
      (x < 120 ? leftY : rightY) += y;
      (x < 120 ? left : right) += 1;
    }
  REQUIRE(left > 0);
  REQUIRE(right > 0);
  CHECK(leftY / left > rightY / right);
}

TEST_CASE("differing pixels are those where any colour channel differs, alpha aside", "[image]") {
  Image a;
  a.width = 3;
  a.height = 1;
  a.rgba = {10, 20, 30, 255, 10, 20, 30, 255, 10, 20, 30, 255};
  Image b = a;
  b.rgba[6] = 31;  // pixel 1, blue
  b.rgba[11] = 0;  // pixel 2, alpha only
  CHECK(differingPixels(a, b) == std::vector<bool>{false, true, false});
  Image c = a;
  c.width = 1;
  c.height = 3;
  CHECK_THROWS_AS(differingPixels(a, c), std::invalid_argument);
}
