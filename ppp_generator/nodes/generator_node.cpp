#include "generator_node.hpp"

#include <iostream>
#include <memory>

#include <nav_msgs/OccupancyGrid.h>

#include "ppp_core/error.hpp"
#include "ppp_core/progress_meter.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_msgs/ProblemSet.h"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/graph_names.h"
#include "remote_failure_fitness.hpp"

namespace ppp {
namespace generator {

GeneratorNode::GeneratorNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, bool /*in_network_thread*/)
    : nh_(nh),
      parameters_(readNodeParameters(private_nh)),
      set_publisher_(nh.advertise<ppp_msgs::ProblemSet>(ppp_msgs::topics::kProblemSet, 1, true)),
      map_publisher_(nh.advertise<nav_msgs::OccupancyGrid>(ppp_msgs::topics::kMap, 1, true)),
      service_(private_nh.advertiseService(ppp_msgs::topics::kGenerate, &GeneratorNode::onGenerate, this)) {}

int GeneratorNode::run() {
  try {
    if (parameters_.generate_on_start) generate(0);
    if (parameters_.exit_when_done) return 0;
    while (!stopping()) ros::WallDuration(0.1).sleep();  // ~generate is served by the caller's threads
  } catch (const Interrupted&) {
    std::cerr << "generator: shut down mid-generation; nothing was written (a rerun generates the set again)\n";
  } catch (const Error& e) {
    ROS_FATAL("generator: %s", e.what());
    return 1;
  }
  return 0;
}

std::size_t GeneratorNode::generate(std::uint64_t seed) {
  std::lock_guard<std::mutex> one_at_a_time(generating_);  // start-up's and ~generate's
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

bool GeneratorNode::onGenerate(ppp_msgs::Generate::Request& request, ppp_msgs::Generate::Response& response) {
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

void GeneratorNode::waitForInitialPool() {
  if (parameters_.wait_for_set.empty()) return;
  ROS_INFO("waiting for %s: its set is this one's initial pool", parameters_.wait_for_set.c_str());
  auto heard = std::make_shared<std::atomic<bool>>(false);  // set in the caller's callback threads
  const ros::Subscriber subscriber = nh_.subscribe<ppp_msgs::ProblemSet>(
      parameters_.wait_for_set, 1, [heard](const ppp_msgs::ProblemSet::ConstPtr&) { *heard = true; });
  while (!*heard) {
    if (stopping()) throw Interrupted();
    ros::WallDuration(0.05).sleep();
  }
}

ProblemSet GeneratorNode::evolve(const GeneratorOptions& options) {
  waitForInitialPool();
  ROS_INFO("generating %d PPPs (%s fitness, %ld matings, seed %lu)", options.population, options.fitness.c_str(),
           options.matings, static_cast<unsigned long>(options.seed));
  // A hunt plays its panel through the simulator's evaluation service, or in process without one.
  const Fitness fitness =
      isPanelFitness(options.fitness) && !parameters_.evaluator.empty()
          ? makeRemoteFailureFitness(nh_, options, parameters_.evaluator, parameters_.evaluator_timeout,
                                       [this] { return stopping(); })
          : fitnessFor(options, parameters_.episode, 0);
  ProgressMeter meter("set '" + (parameters_.set_name.empty() ? options.fitness : parameters_.set_name) + "'",
                      "matings");
  EvolvedSet evolved = evolveSet(
      options, fitness,
      [&meter](long done, long total, double best) {
        const std::string line = meter.update(done, total, steadySeconds(), "best fitness " + formatGeneral(best, 4));
        if (!line.empty()) ROS_INFO("%s", line.c_str());
      },
      std::max(1L, options.matings / 1000), [this] { return stopping(); });  // the meter paces the lines
  ROS_INFO("%s", evolved.summary.c_str());
  if (!parameters_.output_dir.empty()) {
    writeProblemSetDirectory(parameters_.output_dir, evolved.set, options, evolved.extra_files);
    ROS_INFO("wrote the set to %s", parameters_.output_dir.c_str());
  }
  return std::move(evolved.set);
}

ProblemSet GeneratorNode::readExistingSet(const GeneratorOptions& options) {
  if (!evolvedWith(parameters_.output_dir, options)) {
    throw IoError(parameters_.output_dir, "holds a set evolved with other options; remove it or use another output_dir");
  }
  ROS_INFO("resuming: publishing the set already in %s", parameters_.output_dir.c_str());
  return readProblemSetDirectory(parameters_.output_dir);
}

}  // namespace generator
}  // namespace ppp
