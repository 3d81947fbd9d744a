// generator_node: evolves a PPP set with the generator library and publishes it.
//   publishes  problem_set (ppp_msgs/ProblemSet, latched)  the whole set
//              map         (nav_msgs/OccupancyGrid, latched) the set's PPP number ~publish_index
//   service    ~generate   (ppp_msgs/Generate)              evolve again (optionally with another seed)
//   parameters the generator options (config/generator.yaml's keys, docs/reference/options.md#generator), one by
//              one or as YAML text in ~options, and the node's own (docs/reference/options.md#generator-node):
//              ~output_dir, ~publish_index, ~resume, ~evaluator (for the panel fitnesses, failure and regret: the
//              simulator node's ppp_msgs/EvaluateProblems service that plays the panel; empty: the node plays
//              built-in agents itself, under the episode options ~budget, ~sensor_range, ~connectivity, ...),
//              ~wait_for_set (a set topic to hear from before evolving: the generator of initial_pool's set), ...
#include <ros/ros.h>

#include <iostream>

#include <nav_msgs/OccupancyGrid.h>

#include "generator_parameters.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/progress_meter.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_msgs/Generate.h"
#include "ppp_msgs/ProblemSet.h"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/graph_names.h"
#include "remote_failure_fitness.hpp"

namespace ppp {
namespace generator {

/// Runs the generator on demand and publishes what it made.
class GeneratorNode {
 public:
  /// Advertises the topics and the service. @throws InvalidArgument for bad parameters.
  GeneratorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
      : nh_(nh),
        parameters_(readNodeParameters(private_nh)),
        set_publisher_(nh.advertise<ppp_msgs::ProblemSet>(ppp_msgs::topics::kProblemSet, 1, true)),
        map_publisher_(nh.advertise<nav_msgs::OccupancyGrid>(ppp_msgs::topics::kMap, 1, true)),
        service_(private_nh.advertiseService(ppp_msgs::topics::kGenerate, &GeneratorNode::onGenerate, this)) {}

  /// Evolves a set with `seed` (0: the configured one), or with ~resume reads the one already in ~output_dir;
  /// writes and publishes it; returns its size.
  std::size_t generate(std::uint64_t seed) {
    GeneratorOptions options = parameters_.options;
    if (seed != 0) options.seed = seed;
    if (!parameters_.output_dir.empty()) checkOutputDirectory(parameters_.output_dir);
    const ProblemSet set = seed == 0 && parameters_.resume && hasProblemSet(parameters_.output_dir)
                               ? readExistingSet(options)
                               : evolve(options);
    const ppp_msgs::ProblemSet message = ppp_msgs::toSetMessage(
        parameters_.set_name.empty() ? options.fitness : parameters_.set_name, set.problems, set.ids,
        parameters_.resolution);
    nav_msgs::OccupancyGrid map = message.problems[parameters_.publish_index].map;
    map.header.stamp = message.header.stamp;
    set_publisher_.publish(message);
    map_publisher_.publish(map);
    ROS_INFO("published %zu PPPs; map shows %s", set.problems.size(), set.ids[parameters_.publish_index].c_str());
    return set.problems.size();
  }

  /// Whether to evolve at start-up.
  bool generateOnStart() const { return parameters_.generate_on_start; }
  /// Whether to exit once the start-up set is published (a hunt launched on its own).
  bool exitWhenDone() const { return parameters_.exit_when_done; }

 private:
  bool onGenerate(ppp_msgs::Generate::Request& request, ppp_msgs::Generate::Response& response) {
    try {
      response.count = static_cast<std::uint32_t>(generate(request.seed));
      response.success = true;
      response.message = "published " + std::to_string(response.count) + " PPPs";
    } catch (const Error& e) {
      response.success = false;
      response.message = e.what();
      ROS_ERROR("generate failed: %s", e.what());
    }
    return true;
  }

  /// Waits for one message on ~wait_for_set (latched by the generator of the set initial_pool reads, which writes
  /// that set before it publishes it). @throws Interrupted when ROS shuts down first.
  void waitForInitialPool() {
    if (parameters_.wait_for_set.empty()) return;
    ROS_INFO("waiting for %s: its set is this one's initial pool", parameters_.wait_for_set.c_str());
    bool heard = false;
    const ros::Subscriber subscriber = nh_.subscribe<ppp_msgs::ProblemSet>(
        parameters_.wait_for_set, 1, [&heard](const ppp_msgs::ProblemSet::ConstPtr&) { heard = true; });
    for (ros::Rate rate(20); !heard; rate.sleep()) {
      if (!ros::ok()) throw Interrupted();
      ros::spinOnce();
    }
  }

  /// Evolves a set with `options` and writes it to ~output_dir (when set).
  ProblemSet evolve(const GeneratorOptions& options) {
    waitForInitialPool();
    ROS_INFO("generating %d PPPs (%s fitness, %ld matings, seed %lu)", options.population, options.fitness.c_str(),
             options.matings, static_cast<unsigned long>(options.seed));
    // A hunt plays its panel through the simulator's evaluation service, or in process without one.
    const Fitness fitness =
        isPanelFitness(options.fitness) && !parameters_.evaluator.empty()
            ? makeRemoteFailureFitness(nh_, options, parameters_.evaluator, parameters_.evaluator_timeout)
            : fitnessFor(options, parameters_.episode, 0);
    ProgressMeter meter("set '" + (parameters_.set_name.empty() ? options.fitness : parameters_.set_name) + "'",
                        "matings");
    EvolvedSet evolved = evolveSet(
        options, fitness,
        [&meter](long done, long total, double best) {
          const std::string line = meter.update(done, total, steadySeconds(), "best fitness " + formatGeneral(best, 4));
          if (!line.empty()) ROS_INFO("%s", line.c_str());
        },
        std::max(1L, options.matings / 1000), [] { return !ros::ok(); });  // the meter paces the lines
    ROS_INFO("%s", evolved.summary.c_str());
    if (!parameters_.output_dir.empty()) {
      writeProblemSetDirectory(parameters_.output_dir, evolved.set, options, evolved.extra_files);
      ROS_INFO("wrote the set to %s", parameters_.output_dir.c_str());
    }
    return std::move(evolved.set);
  }

  /// The set ~output_dir already holds. @throws IoError when it was evolved with other options.
  ProblemSet readExistingSet(const GeneratorOptions& options) {
    if (!evolvedWith(parameters_.output_dir, options)) {
      throw IoError(parameters_.output_dir, "holds a set evolved with other options; remove it or use another output_dir");
    }
    ROS_INFO("resuming: publishing the set already in %s", parameters_.output_dir.c_str());
    return readProblemSetDirectory(parameters_.output_dir);
  }

  ros::NodeHandle& nh_;
  NodeParameters parameters_;
  ros::Publisher set_publisher_;
  ros::Publisher map_publisher_;
  ros::ServiceServer service_;
};

}  // namespace generator
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "generator");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    ppp::generator::GeneratorNode node(nh, private_nh);
    if (node.generateOnStart()) node.generate(0);
    if (node.exitWhenDone()) return 0;
    ros::spin();
  } catch (const ppp::Interrupted&) {
    // ROS logging is already shut down here.
    std::cerr << "generator: shut down mid-generation; nothing was written (a rerun generates the set again)\n";
    return 0;
  } catch (const ppp::Error& e) {
    ROS_FATAL("generator: %s", e.what());
    return 1;
  }
  return 0;
}
