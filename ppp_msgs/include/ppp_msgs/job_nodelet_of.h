#pragma once

#include <atomic>
#include <exception>
#include <memory>
#include <thread>

#include <nodelet/nodelet.h>
#include <ros/ros.h>

namespace ppp_msgs {

/// The nodelet of a node class that runs a job: `Node(public handle, private handle, in_network_thread = false)`
/// with `int run()`, run in a thread of the nodelet's own, and `stop()`, which makes run() return within a second.
/// Its callbacks are served by the manager's threads, several at a time (the multi-threaded queue). When run()
/// returns by itself its job was the graph's: the nodelet sets its private parameter exit_status to run()'s status and
/// shuts its manager down, as the node's process would exit with that status.
/// Unloading stops and joins the job. A node that cannot start logs why and runs nothing: onInit never throws,
/// since a manager whose nodelet threw there can crash.
template <typename Node>
class JobNodeletOf : public nodelet::Nodelet {
 public:
  ~JobNodeletOf() override {
    unloading_ = true;
    if (node_) node_->stop();
    if (job_.joinable()) job_.join();
  }

 private:
  void onInit() override {
    getPrivateNodeHandle().deleteParam("exit_status");  // an earlier run's, on the same master
    try {
      node_ = std::make_unique<Node>(getMTNodeHandle(), getMTPrivateNodeHandle(), false);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      return;
    }
    job_ = std::thread([this] {
      const int status = node_->run();
      if (!unloading_) {
        getPrivateNodeHandle().setParam("exit_status", status);
        NODELET_INFO("finished (status %d): shutting the nodelet manager down", status);
        ros::requestShutdown();
      }
    });
  }

  std::unique_ptr<Node> node_;
  std::atomic<bool> unloading_{false};
  std::thread job_;
};

}  // namespace ppp_msgs
