// One XML-RPC call over a plain socket with a deadline. roscpp's own master calls
// (ros::master::execute) wait without a bound on a master that accepted the connection and
// hung (SIGSTOPped, swapping): a watch of the master must never block like that.
#pragma once

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

namespace amigobot_tracking {
namespace ros_layer {

// Calls `method` with `params` (an array) at http://host:port/ within `timeout` [s]. Empty on
// success (then *result holds the response's first value; for the ROS APIs [code, status,
// value]), else why not.
std::string callXmlRpc(const std::string& host, int port, const std::string& method,
                       const XmlRpc::XmlRpcValue& params, double timeout, XmlRpc::XmlRpcValue* result);

// host and port of an http://host:port/ URI; false when it is not one.
bool splitHttpUri(const std::string& uri, std::string* host, int* port);

}  // namespace ros_layer
}  // namespace amigobot_tracking
