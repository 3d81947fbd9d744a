// What a local planner's control period costs in ROS 1 messages alone, without the bridge's or a planner's work:
// one process asks, another answers, through TCPROS on loopback, as the planner bridge and a planner in a process
// of its own do.
//
//   period_round_trip_bench answer TOPICS      subscribes to TOPICS and to ask/clock; once every topic's message
//                                              stamped with one time is in, answers a geometry_msgs/TwistStamped
//                                              stamped with it on `cmd_vel`
//   period_round_trip_bench ask TOPICS ROUNDS  waits for the answerer, then ROUNDS times publishes one message on
//                                              each of TOPICS stamped with a new time (and the clock last, if
//                                              listed) and waits for the answer
//
// TOPICS is a comma-separated list of the messages a period sends, of the bridge's types and sizes: map (an 80x80
// nav_msgs/OccupancyGrid), goal (geometry_msgs/PoseStamped), odom (nav_msgs/Odometry), scan (a 360-beam
// sensor_msgs/LaserScan), tf (a tf2_msgs/TFMessage of one transform) and clock (rosgraph_msgs/Clock, which the
// answerer reads but does not wait for). "goal" alone is one round trip of a small message: the floor. Both sides
// read messages in roscpp's network thread, as the bridge and this repository's planners do.
// The asker prints the wall time of a round (median and mean) and the CPU time of each process per round (its own
// from getrusage, the answerer's from /proc).
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <sys/resource.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ppp_msgs/lockstep_queue.h"

namespace {

const std::set<std::string> kTopics = {"map", "goal", "odom", "scan", "tf", "clock"};

std::vector<std::string> topicList(const std::string& text) {
  std::vector<std::string> topics;
  std::stringstream in(text);
  for (std::string topic; std::getline(in, topic, ',');) {
    if (kTopics.count(topic) == 0) {
      throw std::invalid_argument("TOPICS: '" + topic + "' is not one of map, goal, odom, scan, tf, clock");
    }
    topics.push_back(topic);
  }
  if (topics.empty()) throw std::invalid_argument("TOPICS: expected at least one topic");
  return topics;
}

/// Seconds of CPU (user and system) a process has used: this one's, or `pid`'s from /proc.
double cpuSeconds(int pid = 0) {
  if (pid == 0) {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  std::getline(stat, line);
  std::istringstream fields(line.substr(line.rfind(')') + 2));
  std::string field;
  double ticks = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14 || i == 15) ticks += std::stod(field);  // utime, stime
  }
  return ticks / sysconf(_SC_CLK_TCK);
}

/// The newest stamp each waited-for topic has delivered; a period is complete when all have its stamp.
class Arrivals {
 public:
  void expect(const std::string& topic) { stamps_[topic] = ros::Time(); }
  /// Records `stamp` for `topic`; true when every expected topic has it.
  bool arrived(const std::string& topic, const ros::Time& stamp) {
    stamps_[topic] = stamp;
    return std::all_of(stamps_.begin(), stamps_.end(), [&](const auto& kv) { return kv.second == stamp; });
  }

 private:
  std::map<std::string, ros::Time> stamps_;
};

int answer(const std::vector<std::string>& topics) {
  ros::NodeHandle nh;
  ppp_msgs::LockstepQueue queue(true);
  ros::Publisher command = nh.advertise<geometry_msgs::TwistStamped>("cmd_vel", 10);
  std::mutex mutex;
  Arrivals arrivals;
  const auto on = [&](const std::string& topic, const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!arrivals.arrived(topic, stamp)) return;
    geometry_msgs::TwistStamped reply;
    reply.header.stamp = stamp;
    command.publish(reply);
  };
  std::vector<ros::Subscriber> subscribers;
  const auto subscribe = [&](const std::string& topic, auto tag) {
    using Message = decltype(tag);
    ros::SubscribeOptions options;
    options.template init<Message>(topic, 10, [&, topic](const boost::shared_ptr<const Message>& m) {
      if constexpr (std::is_same_v<Message, rosgraph_msgs::Clock>) {
        (void)m;  // read as a planner on simulated time reads it, not waited for
      } else if constexpr (std::is_same_v<Message, tf2_msgs::TFMessage>) {
        on(topic, m->transforms.front().header.stamp);
      } else {
        on(topic, m->header.stamp);
      }
    });
    options.callback_queue = queue.get();
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    subscribers.push_back(nh.subscribe(options));
  };
  for (const std::string& topic : topics) {
    if (topic != "clock") arrivals.expect(topic);
    if (topic == "map") subscribe(topic, nav_msgs::OccupancyGrid());
    if (topic == "goal") subscribe(topic, geometry_msgs::PoseStamped());
    if (topic == "odom") subscribe(topic, nav_msgs::Odometry());
    if (topic == "scan") subscribe(topic, sensor_msgs::LaserScan());
    if (topic == "tf") subscribe(topic, tf2_msgs::TFMessage());
    if (topic == "clock") subscribe(topic, rosgraph_msgs::Clock());
  }
  ros::spin();
  return 0;
}

int ask(const std::vector<std::string>& topics, int rounds) {
  ros::NodeHandle nh;
  ppp_msgs::LockstepQueue queue(true);
  std::mutex mutex;
  std::condition_variable answered;
  ros::Time last_answer;
  int answerer_pid = 0;
  ros::SubscribeOptions options;
  options.init<geometry_msgs::TwistStamped>("cmd_vel", 10, [&](const geometry_msgs::TwistStamped::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    last_answer = m->header.stamp;
    answered.notify_one();
  });
  options.callback_queue = queue.get();
  options.transport_hints = ros::TransportHints().tcpNoDelay();
  ros::Subscriber answers = nh.subscribe(options);
  std::map<std::string, ros::Publisher> publishers;
  for (const std::string& topic : topics) {
    if (topic == "map") publishers[topic] = nh.advertise<nav_msgs::OccupancyGrid>(topic, 1, true);
    if (topic == "goal") publishers[topic] = nh.advertise<geometry_msgs::PoseStamped>(topic, 10);
    if (topic == "odom") publishers[topic] = nh.advertise<nav_msgs::Odometry>(topic, 10);
    if (topic == "scan") publishers[topic] = nh.advertise<sensor_msgs::LaserScan>(topic, 10);
    if (topic == "tf") publishers[topic] = nh.advertise<tf2_msgs::TFMessage>(topic, 100);
    if (topic == "clock") publishers[topic] = nh.advertise<rosgraph_msgs::Clock>(topic, 10, true);
  }
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const auto connected = [&] {
    if (answers.getNumPublishers() == 0) return false;
    return std::all_of(publishers.begin(), publishers.end(), [](auto& kv) { return kv.second.getNumSubscribers() > 0; });
  };
  while (ros::ok() && !connected()) ros::WallDuration(0.05).sleep();
  ros::WallDuration(0.5).sleep();  // every connection's header exchanged both ways
  if (const char* pid = std::getenv("ANSWERER_PID")) answerer_pid = std::atoi(pid);

  nav_msgs::OccupancyGrid map;
  map.header.frame_id = "map";
  map.info.width = map.info.height = 80;
  map.info.resolution = 0.25;
  map.data.assign(80 * 80, -1);
  geometry_msgs::PoseStamped goal;
  goal.header.frame_id = "map";
  nav_msgs::Odometry odom;
  odom.header.frame_id = "robot/odom";
  odom.child_frame_id = "robot/base_link";
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "robot/base_link";
  scan.ranges.assign(360, 2.5f);
  tf2_msgs::TFMessage tf;
  tf.transforms.resize(1);
  tf.transforms[0].header.frame_id = "robot/odom";
  tf.transforms[0].child_frame_id = "robot/base_link";
  rosgraph_msgs::Clock clock;

  std::vector<double> round_us;
  round_us.reserve(rounds);
  const double cpu_start = cpuSeconds();
  const double answerer_start = answerer_pid != 0 ? cpuSeconds(answerer_pid) : 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < rounds && ros::ok(); ++i) {
    const ros::Time stamp(1.0 + 0.1 * i);
    const auto round_start = std::chrono::steady_clock::now();
    for (const std::string& topic : topics) {
      if (topic == "map") map.header.stamp = stamp, publishers[topic].publish(map);
      if (topic == "goal") goal.header.stamp = stamp, publishers[topic].publish(goal);
      if (topic == "odom") odom.header.stamp = stamp, publishers[topic].publish(odom);
      if (topic == "scan") scan.header.stamp = stamp, publishers[topic].publish(scan);
      if (topic == "tf") tf.transforms[0].header.stamp = stamp, publishers[topic].publish(tf);
    }
    if (publishers.count("clock") != 0) clock.clock = stamp, publishers["clock"].publish(clock);
    std::unique_lock<std::mutex> lock(mutex);
    if (!answered.wait_for(lock, std::chrono::seconds(5), [&] { return last_answer == stamp; })) {
      std::fprintf(stderr, "round %d: no answer in 5 s\n", i);
      return 1;
    }
    round_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - round_start)
                           .count());
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpuSeconds() - cpu_start;
  const double answerer_cpu = answerer_pid != 0 ? cpuSeconds(answerer_pid) - answerer_start : 0;
  std::vector<double> sorted = round_us;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  std::printf("%-32s rounds %zu: median %.1f us, mean %.1f us, p90 %.1f us; CPU per round: asker %.1f us, "
              "answerer %.1f us\n",
              [&] {
                std::string joined;
                for (const std::string& t : topics) joined += (joined.empty() ? "" : ",") + t;
                return joined;
              }().c_str(),
              n, sorted[n / 2], 1e6 * wall / n, sorted[n * 9 / 10], 1e6 * cpu / n,
              answerer_pid != 0 ? 1e6 * answerer_cpu / n : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "period_round_trip_bench", ros::init_options::AnonymousName);
  const std::string usage = "usage: period_round_trip_bench answer TOPICS | ask TOPICS ROUNDS";
  try {
    if (argc == 3 && std::string(argv[1]) == "answer") return answer(topicList(argv[2]));
    if (argc == 4 && std::string(argv[1]) == "ask") {
      const int rounds = std::stoi(argv[3]);
      if (rounds < 1 || rounds > 10000000) throw std::invalid_argument("ROUNDS: expected 1 to 10000000");
      return ask(topicList(argv[2]), rounds);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "period_round_trip_bench: %s\n%s\n", e.what(), usage.c_str());
    return 2;
  }
  std::fprintf(stderr, "%s\n", usage.c_str());
  return 2;
}
