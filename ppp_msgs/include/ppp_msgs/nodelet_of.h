#pragma once

#include <exception>
#include <memory>

#include <nodelet/nodelet.h>

namespace ppp_msgs {

/// The nodelet of a node class that serves from its callbacks alone: `Node(public handle, private handle, graph
/// name, in_network_thread = false)`, built when the manager loads it and destroyed when it unloads it. A node that
/// cannot start (a bad parameter) logs why and serves nothing: onInit never throws, since a manager whose nodelet
/// threw there can crash.
template <typename Node>
class NodeletOf : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      node_ = std::make_unique<Node>(getNodeHandle(), getPrivateNodeHandle(), getName(), false);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
    }
  }

  std::unique_ptr<Node> node_;
};

}  // namespace ppp_msgs
