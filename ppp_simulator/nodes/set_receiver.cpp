#include "set_receiver.hpp"

#include <map>
#include <memory>
#include <mutex>

#include "hunt_server.hpp"
#include "ppp_core/error.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/graph_names.h"
#include "ppp_simulator/experiment_graph.hpp"

namespace ppp {
namespace simulator {

namespace {

/// The set a generator node published for `spec`, ready to play. @throws ParseError naming the topic.
agents::PreparedSet prepareReceived(const SetSpec& spec, const ppp_msgs::ProblemSet& message, const ExperimentConfig& config,
                            const std::string& output_dir) {
  const std::string topic = setTopic(spec.name);
  if (message.name != spec.name) {
    throw ParseError(topic, 0, "name", "expected set '" + spec.name + "', got '" + message.name + "'");
  }
  std::vector<Problem> problems;
  for (const ppp_msgs::Problem& m : message.problems) problems.push_back(ppp_msgs::fromMessage(m));
  agents::PreparedSet set = agents::prepareSet(
      spec.name, generator::problemSetFromProblems(std::move(problems), spec.generator->weights, topic),
      config.episode);
  set.directory = output_dir + "/sets/" + spec.name;  // where the generator node wrote its trees
  return set;
}

}  // namespace

ReceivedSets receiveSets(ros::NodeHandle& nh, ros::NodeHandle& services_nh, const ExperimentConfig& config,
                         const SimulatorParameters& parameters, const NodeControl& control) {
  /// A set a generator node is to publish.
  struct Awaited {
    std::string name;
    ros::Subscriber subscriber;
    ros::WallTime last_seen;  // when the topic last had a publisher
  };
  std::mutex mutex;
  std::map<std::string, ppp_msgs::ProblemSet::ConstPtr> received;
  std::vector<Awaited> awaited;
  bool hunting = false;
  for (const SetSpec& spec : config.sets) {
    if (!spec.generator) continue;
    hunting = hunting || generator::isPanelFitness(spec.generator->fitness);
    const std::string name = spec.name;
    awaited.push_back({name,
                       nh.subscribe<ppp_msgs::ProblemSet>(
                           setTopic(name), 1,
                           [&mutex, &received, name](const ppp_msgs::ProblemSet::ConstPtr& m) {
                             std::lock_guard<std::mutex> lock(mutex);
                             received[name] = m;
                           }),
                       ros::WallTime::now()});
    ROS_INFO("waiting for set '%s' from %s", name.c_str(), setTopic(name).c_str());
  }
  std::unique_ptr<HuntServer> hunt_server;
  ros::ServiceServer hunt_service;
  if (hunting) {
    hunt_server = std::make_unique<HuntServer>(nh, parameters, control);
    hunt_service = services_nh.advertiseService(ppp_msgs::topics::kEvaluate, &HuntServer::evaluate, hunt_server.get());
    ROS_INFO("serving %s for the hunting generator nodes", hunt_service.getService().c_str());
  }
  for (;;) {
    if (control.stopping()) return {};
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (received.size() == awaited.size()) break;
    }
    const ros::WallTime now = ros::WallTime::now();
    for (Awaited& a : awaited) {
      if (a.subscriber.getNumPublishers() > 0) a.last_seen = now;
      if ((now - a.last_seen).toSec() > parameters.set_timeout) {
        throw IoError(setTopic(a.name), "no generator node publishes set '" + a.name + "' (node " +
                                            generatorNodeName(a.name) + ", seen last " +
                                            std::to_string(parameters.set_timeout) + " s ago or never); is it running?");
      }
    }
    ros::WallDuration(0.2).sleep();
  }
  hunt_service.shutdown();
  hunt_server.reset();  // its lanes close before the experiment's open on the same topics
  ReceivedSets result;
  for (const SetSpec& spec : config.sets) {
    if (spec.generator) {
      result.messages.push_back(*received[spec.name]);
      result.sets.push_back(prepareReceived(spec, result.messages.back(), config, parameters.output_dir));
    } else {
      result.sets.push_back(agents::prepareSet(spec.name, generator::readProblemSetDirectory(spec.directory),
                                       config.episode));
      result.sets.back().directory = spec.directory;
      result.messages.push_back(ppp_msgs::toSetMessage(spec.name, result.sets.back().set.problems,
                                                         result.sets.back().set.ids, parameters.resolution));
    }
  }
  return result;
}

}  // namespace simulator
}  // namespace ppp
