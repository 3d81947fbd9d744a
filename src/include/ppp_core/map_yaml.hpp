#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "ppp_core/problem.hpp"

namespace ppp {

/// Largest map YAML file the reader accepts, checked before reading it.
constexpr std::size_t kMaxMapYamlBytes = 64u << 20;
/// Largest PGM image file the reader accepts, checked before reading it.
constexpr std::size_t kMaxPgmBytes = 256u << 20;

/// Pixel value written for a free cell (map_server reads it as free with the default thresholds).
constexpr int kPgmFreeValue = 254;
/// Pixel value written for an obstacle cell (map_server reads it as occupied).
constexpr int kPgmOccupiedValue = 0;
/// occupied_thresh written to every exported YAML (map_server's usual value).
constexpr double kDefaultOccupiedThresh = 0.65;
/// free_thresh written to every exported YAML (map_server's usual value).
constexpr double kDefaultFreeThresh = 0.196;

/// Where the exported map sits in the ROS `map` frame (the map_server `resolution` and `origin` keys).
struct MapYamlOptions {
  double resolution = 1.0;  ///< Metres per cell; must be finite and > 0.
  double origin_x = 0.0;    ///< Map-frame x, in metres, of the bottom-left corner of the image.
  double origin_y = 0.0;    ///< Map-frame y, in metres, of the bottom-left corner of the image.
  double origin_yaw = 0.0;  ///< Rotation of the map, in radians (map_server ignores it; kept for completeness).

  /// Checks the options. @throws InvalidArgument naming the option.
  void validate() const;
};

/// Choices for importing a foreign map: a map_server map without the ppp_* keys (ignored for maps PPP Lab wrote
/// with them) or a MovingAI `.map`.
struct MapImportOptions {
  std::optional<Cell> start;  ///< Start cell in grid coordinates; default top-left (0, 0), in a .map the first free.
  std::optional<Cell> goal;   ///< Goal cell in grid coordinates; default bottom-right, in a .map the last free.
};

/// A map_server map in memory: the YAML text and the bytes of the PGM image it names.
struct MapYamlText {
  std::string yaml;  ///< The map YAML.
  std::string pgm;   ///< The PGM image (binary P5).
};

/// The map writeMapYaml() writes, as text: the YAML (its image key `image_name`) and the PGM image.
/// @throws InvalidArgument for an invalid problem or options.
MapYamlText formatMapYaml(const Problem& problem, const std::string& image_name, const MapYamlOptions& options = {});

/// Gives the bytes of the image a map YAML names, from its path (resolved against the YAML's directory).
/// @throws IoError when it cannot be read.
using MapImageSource = std::function<std::string(const std::string& image_path)>;

/// Writes a map_server-style map: `<stem>.pgm` (binary P5, free 254, occupied 0, row 0 = top of the map)
/// next to `yaml_path`, then the YAML (image, resolution, origin, negate, thresholds) plus the ppp_* keys
/// (ppp_size, ppp_start, ppp_goal, ppp_max_obstacles, ppp_obstacles, ppp_metadata) that make
/// readMapYaml() give back the identical problem. Both files are written atomically.
/// @throws InvalidArgument for an invalid problem or options, IoError when a file cannot be written.
void writeMapYaml(const Problem& problem, const std::string& yaml_path, const MapYamlOptions& options = {});

/// Reads a map_server-style YAML and its PGM image (P5 or P2, maxval <= 255, '#' comments allowed).
/// Pixels are classified as map_server's trinary mode does: p = (255 - v) / 255 (v / 255 when negate),
/// occupied if p > occupied_thresh, free if p < free_thresh, otherwise unknown; unknown cells are treated
/// as obstacles, since a planner must not cross them. Values of images with maxval < 255 are first
/// scaled to 0..255 (v * 255 / maxval, as SDL_image does for map_server).
/// With the ppp_* keys the problem is rebuilt from them and the image must agree with the decoded grid
/// cell by cell; without them (a foreign map) every horizontal run of obstacle cells becomes one `hbar`
/// descriptor, max_obstacles is their count and start and goal come from `options`.
/// When `geometry` is given it receives the map's resolution and origin.
/// @throws IoError when a file cannot be read, ParseError "<file>:<line>: <field>: <what>" for bad content,
/// InvalidArgument when an option's start or goal lies outside the image.
Problem readMapYaml(const std::string& yaml_path, const MapImportOptions& options = {},
                    MapYamlOptions* geometry = nullptr);

/// readMapYaml() on text: `yaml` is the map YAML of `yaml_path` (named in errors; the image is resolved against
/// its directory) and `image` gives the bytes of the PGM image it names.
/// @throws what readMapYaml() throws (IoError only from `image`).
Problem parseMapYaml(const std::string& yaml, const std::string& yaml_path, const MapImageSource& image,
                     const MapImportOptions& options = {}, MapYamlOptions* geometry = nullptr);

}  // namespace ppp
