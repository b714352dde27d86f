// One nodelet wrapper for every node of the package: the node is built (and, when it has a
// start(), started) in onInit. The error convention: a node's constructor or start() throws
// std::runtime_error naming the parameter; no exception leaves onInit (it would take the
// whole manager down): it is logged with ROS_FATAL naming the nodelet, the half-built node
// is destroyed at once, and the nodelet stays loaded but inert (no topics, timers or
// services, so nothing can enable it).
#pragma once

#include <exception>
#include <memory>
#include <type_traits>
#include <utility>

#include <nodelet/nodelet.h>
#include <ros/ros.h>

namespace amigobot_tracking {
namespace ros_layer {

namespace nodelet_host_detail {
template <class Node, class = void>
struct HasStart : std::false_type {};
template <class Node>
struct HasStart<Node, std::void_t<decltype(std::declval<Node&>().start())>> : std::true_type {};
}  // namespace nodelet_host_detail

// Node(ros::NodeHandle nh, ros::NodeHandle pnh). kName: in the fatal message ("<kName> not
// started: <why>"). kMultiThreaded: the manager's multi-threaded callback queue.
template <class Node, const char* kName, bool kMultiThreaded = false>
class NodeletHost : public nodelet::Nodelet {
 public:
  ~NodeletHost() override { node_.reset(); }  // before the node handles go

  bool running() const { return node_ != nullptr; }

 private:
  void onInit() override {
    try {
      std::unique_ptr<Node> node = kMultiThreaded
                                       ? std::make_unique<Node>(getMTNodeHandle(), getMTPrivateNodeHandle())
                                       : std::make_unique<Node>(getNodeHandle(), getPrivateNodeHandle());
      if constexpr (nodelet_host_detail::HasStart<Node>::value) node->start();  // destroyed on throw
      node_ = std::move(node);
    } catch (const std::exception& e) {
      NODELET_FATAL_STREAM(kName << " not started: " << e.what() << ". Nothing runs; fix it and reload.");
    } catch (...) {
      NODELET_FATAL_STREAM(kName << " not started: unknown exception. Nothing runs; fix it and reload.");
    }
  }

  std::unique_ptr<Node> node_;  // destroyed on unload: each node stops itself cleanly
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
