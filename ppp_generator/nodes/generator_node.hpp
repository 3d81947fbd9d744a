#pragma once

// The generator node: evolves a PPP set with the generator library and publishes it.
//   publishes  problem_set (ppp_msgs/ProblemSet, latched)  the whole set
//              map         (nav_msgs/OccupancyGrid, latched) the set's PPP number ~publish_index
//   service    ~generate   (ppp_msgs/Generate)              evolve again (optionally with another seed)
//   parameters the generator options (config/generator.yaml's keys, docs/reference/options.md#generator), one by
//              one or as YAML text in ~options, and the node's own (docs/reference/options.md#generator-node):
//              ~output_dir, ~publish_index, ~resume, ~evaluator (for the panel fitnesses, failure and regret: the
//              simulator node's ppp_msgs/EvaluateProblems service that plays the panel; empty: the node plays
//              built-in agents itself, under the episode options ~budget, ~sensor_range, ~connectivity, ...),
//              ~wait_for_set (a set topic to hear from before evolving: the generator of initial_pool's set), ...
// It runs as a process of its own (generator_node) or as the nodelet ppp_generator/Generator.

#include <atomic>
#include <cstdint>
#include <mutex>

#include <ros/ros.h>

#include "generator_parameters.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_msgs/Generate.h"

namespace ppp {
namespace generator {

/// Runs the generator on demand and publishes what it made.
class GeneratorNode {
 public:
  /// Advertises the topics and the service; its callbacks (the service, ~wait_for_set's set) must be served by the
  /// caller's threads (a spinner, or a nodelet manager); `in_network_thread` is unused. @throws InvalidArgument for
  /// bad parameters.
  GeneratorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, bool in_network_thread);

  /// Evolves at start-up when ~generate_on_start says so; with ~exit_when_done returns then, else serves ~generate
  /// until stop() or ROS shuts down. Returns the exit status (0, or 1 after an error, logged).
  int run();
  /// Makes run() return (any thread); a generation under way stops at its next mating round, writing nothing.
  void stop() { stop_requested_ = true; }

  /// Evolves a set with `seed` (0: the configured one), or with ~resume reads the one already in ~output_dir;
  /// writes and publishes it; returns its size.
  std::size_t generate(std::uint64_t seed);

 private:
  bool stopping() const { return stop_requested_ || !ros::ok(); }
  bool onGenerate(ppp_msgs::Generate::Request& request, ppp_msgs::Generate::Response& response);
  /// Waits for one message on ~wait_for_set (latched by the generator of the set initial_pool reads, which writes
  /// that set before it publishes it). @throws Interrupted when the node stops first.
  void waitForInitialPool();
  /// Evolves a set with `options` and writes it to ~output_dir (when set).
  ProblemSet evolve(const GeneratorOptions& options);
  /// The set ~output_dir already holds. @throws IoError when it was evolved with other options.
  ProblemSet readExistingSet(const GeneratorOptions& options);

  ros::NodeHandle nh_;
  NodeParameters parameters_;
  std::atomic<bool> stop_requested_{false};
  std::mutex generating_;
  ros::Publisher set_publisher_;
  ros::Publisher map_publisher_;
  ros::ServiceServer service_;
};

}  // namespace generator
}  // namespace ppp
