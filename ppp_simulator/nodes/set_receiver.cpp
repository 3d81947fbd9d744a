#include "set_receiver.hpp"

#include <map>
#include <memory>
#include <mutex>

#include "hunt_server.hpp"
#include "ppp_core/error.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/topic_names.h"
#include "ppp_simulator/experiment_graph.hpp"

namespace ppp {
namespace simulator {

namespace {

/// The set a generator node published for `spec`, ready to play. @throws ParseError naming the topic.
PreparedSet prepareReceived(const SetSpec& spec, const ppp_msgs::ProblemSet& message, const ExperimentConfig& config,
                            const std::string& output_dir) {
  const std::string topic = setTopic(spec.name);
  if (message.name != spec.name) {
    throw ParseError(topic, 0, "name", "expected set '" + spec.name + "', got '" + message.name + "'");
  }
  std::vector<Problem> problems;
  for (const ppp_msgs::Problem& m : message.problems) problems.push_back(ppp_msgs::fromMessage(m));
  PreparedSet set = prepareSet(
      spec.name, generator::problemSetFromProblems(std::move(problems), spec.generator->weights, topic),
      config.episode.sensor_range);
  set.directory = output_dir + "/sets/" + spec.name;  // where the generator node wrote its trees
  return set;
}

}  // namespace

ppp_msgs::ProblemSet setMessage(const PreparedSet& set, double resolution) {
  ppp_msgs::ProblemSet m;
  m.header.stamp = ros::Time::now();
  m.header.frame_id = "map";
  m.name = set.name;
  for (std::size_t i = 0; i < set.set.problems.size(); ++i) {
    m.problems.push_back(ppp_msgs::toMessage(set.set.problems[i], set.set.ids[i], resolution));
  }
  return m;
}

ReceivedSets receiveSets(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const ExperimentConfig& config,
                         const SimulatorParameters& parameters) {
  std::mutex mutex;
  std::map<std::string, ppp_msgs::ProblemSet::ConstPtr> received;
  std::vector<ros::Subscriber> subscribers;
  std::map<std::string, ros::WallTime> last_seen;
  bool hunting = false;
  for (const SetSpec& spec : config.sets) {
    if (!spec.generator) continue;
    hunting = hunting || spec.generator->fitness == generator::kFailureFitness;
    const std::string name = spec.name;
    subscribers.push_back(nh.subscribe<ppp_msgs::ProblemSet>(
        setTopic(name), 1, [&mutex, &received, name](const ppp_msgs::ProblemSet::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(mutex);
          received[name] = m;
        }));
    last_seen[name] = ros::WallTime::now();
    ROS_INFO("waiting for set '%s' from %s", name.c_str(), setTopic(name).c_str());
  }
  std::unique_ptr<HuntServer> hunt_server;
  ros::ServiceServer hunt_service;
  if (hunting) {
    hunt_server = std::make_unique<HuntServer>(nh, parameters);
    hunt_service = private_nh.advertiseService(ppp_msgs::topics::kEvaluate, &HuntServer::evaluate, hunt_server.get());
    ROS_INFO("serving %s for the hunting generator nodes", hunt_service.getService().c_str());
  }
  for (;;) {
    if (!ros::ok()) return {};
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (received.size() == last_seen.size()) break;
    }
    for (std::size_t i = 0, s = 0; s < config.sets.size(); ++s) {
      if (!config.sets[s].generator) continue;
      const std::string& name = config.sets[s].name;
      const ros::WallTime now = ros::WallTime::now();
      if (subscribers[i++].getNumPublishers() > 0) last_seen[name] = now;
      if ((now - last_seen[name]).toSec() > parameters.set_timeout) {
        throw IoError(setTopic(name), "no generator node publishes set '" + name + "' (node " +
                                          generatorNodeName(name) + ", seen last " +
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
      result.sets.push_back(prepareSet(spec.name, generator::readProblemSetDirectory(spec.directory),
                                       config.episode.sensor_range));
      result.sets.back().directory = spec.directory;
      result.messages.push_back(setMessage(result.sets.back(), parameters.resolution));
    }
  }
  return result;
}

}  // namespace simulator
}  // namespace ppp
