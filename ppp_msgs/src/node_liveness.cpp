#include "ppp_msgs/node_liveness.h"

#include <cerrno>
#include <string>

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <ros/master.h>
#include <ros/network.h>
#include <ros/this_node.h>
#include <ros/xmlrpc_manager.h>
#include <xmlrpcpp/XmlRpcClient.h>

namespace ppp_msgs {

namespace {

constexpr int kConnectTimeoutMs = 2000;  // a node on a live link answers a connect in well under a millisecond

/// Whether a TCP connection to host:port opens within kConnectTimeoutMs. xmlrpcpp's blocking client would wait
/// out the kernel's connect retries (about two minutes) on a cut network link; this gives up in two seconds.
bool connects(const std::string& host, std::uint32_t port) {
  addrinfo hints{};
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0) return false;
  bool open = false;
  const int fd = socket(found->ai_family, found->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, found->ai_protocol);
  if (fd >= 0) {
    if (connect(fd, found->ai_addr, found->ai_addrlen) == 0) {
      open = true;
    } else if (errno == EINPROGRESS) {
      pollfd waiting{fd, POLLOUT, 0};
      int error = 0;
      socklen_t length = sizeof(error);
      open = poll(&waiting, 1, kConnectTimeoutMs) == 1 && getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) == 0 &&
             error == 0;
    }
    close(fd);
  }
  freeaddrinfo(found);
  return open;
}

}  // namespace

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
      // A publisher in this very process (a nodelet of the same manager) is alive while this code runs; asking
      // the process's own XML-RPC server, whose thread a loaded manager may not serve in time, could say otherwise.
      if (static_cast<std::string>(uri) == ros::XMLRPCManager::instance()->getServerURI()) return true;
      std::string host;
      std::uint32_t port = 0;
      if (!ros::network::splitURI(static_cast<std::string>(uri), host, port) || !connects(host, port)) continue;
      XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
      XmlRpc::XmlRpcValue pid_args, pid;
      pid_args[0] = ros::this_node::getName();
      if (client.execute("getPid", pid_args, pid) && !client.isFault()) return true;
    }
  }
  return false;
}

}  // namespace ppp_msgs
