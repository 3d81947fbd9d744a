#include "ppp_msgs/node_liveness.h"

#include <ros/master.h>
#include <ros/network.h>
#include <ros/this_node.h>
#include <xmlrpcpp/XmlRpcClient.h>

namespace ppp_msgs {

bool publisherAlive(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, state;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, state, false)) return true;  // cannot tell
  for (int i = 0; i < state[0].size(); ++i) {
    if (static_cast<std::string>(state[0][i][0]) != topic) continue;
    for (int j = 0; j < state[0][i][1].size(); ++j) {
      XmlRpc::XmlRpcValue lookup_args, lookup_result, uri;
      lookup_args[0] = ros::this_node::getName();
      lookup_args[1] = state[0][i][1][j];
      if (!ros::master::execute("lookupNode", lookup_args, lookup_result, uri, false)) continue;
      std::string host;
      std::uint32_t port = 0;
      if (!ros::network::splitURI(static_cast<std::string>(uri), host, port)) continue;
      XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
      XmlRpc::XmlRpcValue pid_args, pid;
      pid_args[0] = ros::this_node::getName();
      if (client.execute("getPid", pid_args, pid) && !client.isFault()) return true;
    }
  }
  return false;
}

}  // namespace ppp_msgs
