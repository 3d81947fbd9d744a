#pragma once

#include <string>

namespace ppp_msgs {

/// True while some node publishing `topic` answers on its XML-RPC API, or when the master cannot be asked. A node
/// whose API does not accept a connection within two seconds (a cut network link) counts as gone.
/// A killed node stays registered with the master (and a subscriber keeps retrying its link), so neither the
/// registration nor a connection count says whether the publisher is still there; this asks the process.
bool publisherAlive(const std::string& topic);

}  // namespace ppp_msgs
