// The process's watch of its ROS master. TCPROS connections between running nodes outlive
// the master, so a stack keeps running when it dies; but a restarted master knows nothing of
// the process, roscpp never registers again, and new nodes (a `rosservice call`, a new
// cmd_vel or target publisher, rosout) cannot reach it. This watch polls the master's pid
// (ros/xmlrpc_call.h: bounded, a hung master cannot block it) on a thread of its own and,
// when another master answers, registers every publisher, subscriber and service of this
// process with it again, through the same XML-RPC calls roscpp made at start-up. One watch
// per process, shared by the nodelets of a manager (they are one ROS node). Users poll
// state() from their own timers: the driver stops the robot and the tracking nodelet
// disables tracking while the master has been unreachable too long.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include <xmlrpcpp/XmlRpcValue.h>

#include "amigobot_tracking/ros/master_presence.h"

namespace amigobot_tracking {
namespace ros_layer {

class MasterWatch {
 public:
  static constexpr double kPollPeriod = 0.2;   // [s] (a new TCP connection each: ~6 kB/s at 5 Hz across a link)
  static constexpr double kCallTimeout = 0.3;  // [s] per XML-RPC call

  struct State {
    bool reachable = false;
    double unreachable_for = 0.0;  // [s] since the master last answered
    std::uint64_t registrations = 0;  // times everything was registered with a new master
    std::string last_registration;    // what the last one did ("12 publishers, ...")
    std::optional<std::string> identity;  // the pid of the master that answered last
  };

  // The process's watch, started at the first call; it stops when the last holder lets go.
  static std::shared_ptr<MasterWatch> shared();
  ~MasterWatch();
  MasterWatch(const MasterWatch&) = delete;
  MasterWatch& operator=(const MasterWatch&) = delete;

  State state() const;

 private:
  MasterWatch();
  void run();
  // The master's pid, or nullopt (then *error says why).
  std::optional<std::string> pollPid(std::string* error);
  // The services this node provides, as the master lists them (kept for a new master).
  void rememberServices();
  // Every publication, subscription and remembered service of this process, registered with
  // the master that now answers; returns a summary for the log.
  std::string registerEverything();
  std::string callMaster(const std::string& method, const XmlRpc::XmlRpcValue& params, XmlRpc::XmlRpcValue* result);
  std::string callSelf(const std::string& method, const XmlRpc::XmlRpcValue& params, XmlRpc::XmlRpcValue* result);

  std::string master_host_;
  int master_port_ = 0;
  mutable std::mutex mutex_;
  MasterPresence presence_;  // mutex_
  State state_;              // mutex_ (unreachable_for computed in state())
  std::set<std::string> services_;  // poll thread only
  double next_service_refresh_ = 0.0;
  double service_refresh_ = 1.0;  // [s] doubles up to 30 s (master_watch.cpp)
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
