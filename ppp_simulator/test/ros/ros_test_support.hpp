#pragma once

// Helpers shared by the ROS tests: child processes, scratch directories, result counting, node pids.

#include <ros/ros.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <condition_variable>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>

#include "ppp_core/text_file.hpp"
#include "ppp_msgs/EpisodeResults.h"

namespace ppp {
namespace simulator {
namespace test {

/// A shell command run as a child process, its output captured in a file.
class Child {
 public:
  Child(const std::string& command, const std::string& log) : log_(log) {
    pid_ = ::fork();
    if (pid_ == 0) {
      ::execl("/bin/sh", "sh", "-c", (command + " > " + log + " 2>&1").c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
  }
  /// Waits for the exit; returns the exit status (128 + signal when killed).
  int wait() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  /// Sends a signal to the shell's child (the node) and the shell.
  void kill(int signal) {
    const std::string command = "pkill -" + std::to_string(signal) + " -P " + std::to_string(pid_);
    if (std::system(command.c_str()) != 0) ::kill(pid_, signal);
  }
  /// What the command printed.
  std::string output() const { return readTextFile(log_, 1u << 24); }

 private:
  pid_t pid_;
  std::string log_;
};

/// Counts the results published on /ppp/results, per agent.
class ResultCounter {
 public:
  ResultCounter() { subscriber_ = nh_.subscribe("/ppp/results", 1000, &ResultCounter::onResult, this); }
  /// Waits (up to `seconds`) until `agent` has at least `count` results; false on time-out.
  bool waitFor(const std::string& agent, int count, double seconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return counts_[agent] >= count; });
  }

 private:
  void onResult(const ppp_msgs::EpisodeResults::ConstPtr& group) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const ppp_msgs::EpisodeResult& result : group->results) ++counts_[result.agent];
    changed_.notify_all();
  }
  ros::NodeHandle nh_;
  ros::Subscriber subscriber_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, int> counts_;
};

/// A fresh scratch directory `name` for this test process.
inline std::string scratch(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("ppp_ros_test_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir.parent_path());
  return dir.string();
}

/// The pid of a running node, asked through its XML-RPC API (-1 when it cannot be reached).
inline int nodePid(const std::string& node) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = node;
  if (!ros::master::execute("lookupNode", args, result, payload, true)) return -1;
  const std::string uri = payload;  // http://host:port/
  const auto host_start = uri.find("://") + 3;
  const auto colon = uri.find(':', host_start);
  const auto slash = uri.find('/', colon);
  XmlRpc::XmlRpcClient client(uri.substr(host_start, colon - host_start).c_str(),
                              std::stoi(uri.substr(colon + 1, slash - colon - 1)), "/");
  XmlRpc::XmlRpcValue pid_args, pid_result;
  pid_args[0] = ros::this_node::getName();
  if (!client.execute("getPid", pid_args, pid_result)) return -1;
  return static_cast<int>(pid_result[2]);
}

}  // namespace test
}  // namespace simulator
}  // namespace ppp
