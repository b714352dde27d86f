#include "amigobot_tracking/ros/master_watch.h"

#include <algorithm>
#include <chrono>

#include <ros/connection_manager.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <ros/service_manager.h>
#include <ros/xmlrpc_manager.h>

#include "amigobot_tracking/link/system_clock_errors.h"
#include "amigobot_tracking/ros/xmlrpc_call.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

// [s] how often the services this node provides are listed: getSystemState answers with the whole
// graph (tens of kB with two robots), which across a Wi-Fi to a master on the other robot cost
// 35 kB/s at 1 Hz. Services are advertised at start-up, so the interval doubles from 1 s to 30 s.
constexpr double kServiceRefreshLast = 30.0;

XmlRpc::XmlRpcValue args(std::initializer_list<std::string> values) {
  XmlRpc::XmlRpcValue a;
  a.setSize(0);
  int i = 0;
  for (const std::string& v : values) a[i++] = v;
  return a;
}

// A ROS API answer [code, status, value] with code 1.
bool succeeded(XmlRpc::XmlRpcValue& r) {
  return r.getType() == XmlRpc::XmlRpcValue::TypeArray && r.size() == 3 &&
         r[0].getType() == XmlRpc::XmlRpcValue::TypeInt && static_cast<int>(r[0]) == 1;
}

// `publishers` (URIs the master lists for `topic`) and every publisher this node receives
// `topic` from now (getBusInfo: [id, publisher URI, 'i', transport, topic, ...]).
XmlRpc::XmlRpcValue withConnectedPublishers(XmlRpc::XmlRpcValue publishers, const std::string& topic,
                                            XmlRpc::XmlRpcValue& bus) {
  if (publishers.getType() != XmlRpc::XmlRpcValue::TypeArray) publishers = args({});
  if (!succeeded(bus) || bus[2].getType() != XmlRpc::XmlRpcValue::TypeArray) return publishers;
  std::set<std::string> known;
  for (int i = 0; i < publishers.size(); ++i) known.insert(static_cast<std::string>(publishers[i]));
  for (int i = 0; i < bus[2].size(); ++i) {
    XmlRpc::XmlRpcValue& c = bus[2][i];
    if (c.getType() != XmlRpc::XmlRpcValue::TypeArray || c.size() < 5) continue;
    if (static_cast<std::string>(c[2]) != "i" || static_cast<std::string>(c[4]) != topic) continue;
    const std::string uri = c[1];
    if (known.insert(uri).second) publishers[publishers.size()] = uri;
  }
  return publishers;
}

}  // namespace

std::shared_ptr<MasterWatch> MasterWatch::shared() {
  static std::mutex mutex;
  static std::weak_ptr<MasterWatch> instance;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<MasterWatch> watch = instance.lock();
  if (!watch) {
    watch.reset(new MasterWatch());
    instance = watch;
  }
  return watch;
}

MasterWatch::MasterWatch() : master_host_(ros::master::getHost()), master_port_(ros::master::getPort()) {
  thread_ = std::thread([this] { run(); });
}

MasterWatch::~MasterWatch() {
  stop_ = true;
  thread_.join();
}

MasterWatch::State MasterWatch::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  State s = state_;
  s.reachable = presence_.reachable();
  s.unreachable_for = presence_.unreachableFor(link::steadySeconds());
  s.identity = presence_.identity();
  return s;
}

std::string MasterWatch::callMaster(const std::string& method, const XmlRpc::XmlRpcValue& params,
                                    XmlRpc::XmlRpcValue* result) {
  const std::string error = callXmlRpc(master_host_, master_port_, method, params, kCallTimeout, result);
  if (!error.empty()) return error;
  return succeeded(*result) ? "" : method + " refused by the master";
}

std::string MasterWatch::callSelf(const std::string& method, const XmlRpc::XmlRpcValue& params,
                                  XmlRpc::XmlRpcValue* result) {
  std::string host;
  int port = 0;
  if (!splitHttpUri(ros::XMLRPCManager::instance()->getServerURI(), &host, &port)) return "no XML-RPC server URI";
  const std::string error = callXmlRpc(host, port, method, params, kCallTimeout, result);
  if (!error.empty()) return error;
  return succeeded(*result) ? "" : method + " refused by this node";
}

std::optional<std::string> MasterWatch::pollPid(std::string* error) {
  XmlRpc::XmlRpcValue r;
  *error = callMaster("getPid", args({ros::this_node::getName()}), &r);
  if (!error->empty()) return std::nullopt;
  if (r[2].getType() != XmlRpc::XmlRpcValue::TypeInt) {
    *error = "getPid: no pid";
    return std::nullopt;
  }
  return std::to_string(static_cast<int>(r[2]));
}

void MasterWatch::rememberServices() {
  XmlRpc::XmlRpcValue r;
  if (!callMaster("getSystemState", args({ros::this_node::getName()}), &r).empty()) return;
  XmlRpc::XmlRpcValue& services = r[2][2];
  if (services.getType() != XmlRpc::XmlRpcValue::TypeArray) return;
  const std::string me = ros::this_node::getName();
  for (int i = 0; i < services.size(); ++i) {
    XmlRpc::XmlRpcValue& providers = services[i][1];
    for (int k = 0; k < providers.size(); ++k) {
      if (static_cast<std::string>(providers[k]) == me) services_.insert(static_cast<std::string>(services[i][0]));
    }
  }
}

std::string MasterWatch::registerEverything() {
  const std::string me = ros::this_node::getName();
  const std::string api = ros::XMLRPCManager::instance()->getServerURI();
  int publishers = 0, subscribers = 0, services = 0;
  std::string failures;
  XmlRpc::XmlRpcValue pubs, subs, r;
  if (callSelf("getPublications", args({me}), &pubs).empty()) {
    for (int i = 0; i < pubs[2].size(); ++i) {
      const std::string topic = pubs[2][i][0], type = pubs[2][i][1];
      if (callMaster("registerPublisher", args({me, topic, type, api}), &r).empty()) ++publishers;
      else failures += " " + topic;
    }
  }
  XmlRpc::XmlRpcValue bus;
  callSelf("getBusInfo", args({me}), &bus);
  if (callSelf("getSubscriptions", args({me}), &subs).empty()) {
    for (int i = 0; i < subs[2].size(); ++i) {
      const std::string topic = subs[2][i][0], type = subs[2][i][1];
      if (!callMaster("registerSubscriber", args({me, topic, type, api}), &r).empty()) {
        failures += " " + topic;
        continue;
      }
      // The publishers that registered before us: hand them to our own subscription, as the
      // master does for the ones that register later (publisherUpdate). The update is the
      // whole list (roscpp drops connections to publishers not in it), so it keeps those we
      // are connected to: a node that never registers again must not be cut off.
      XmlRpc::XmlRpcValue update = args({"/master", topic});
      update[2] = withConnectedPublishers(r[2], topic, bus);
      XmlRpc::XmlRpcValue ignored;
      callSelf("publisherUpdate", update, &ignored);
      ++subscribers;
    }
  }
  const std::string service_api =
      "rosrpc://" + ros::network::getHost() + ":" + std::to_string(ros::ConnectionManager::instance()->getTCPPort());
  for (const std::string& name : services_) {
    if (!ros::ServiceManager::instance()->lookupServicePublication(name)) continue;  // since shut down
    if (callMaster("registerService", args({me, name, service_api, api}), &r).empty()) ++services;
    else failures += " " + name;
  }
  std::string summary = std::to_string(publishers) + " publishers, " + std::to_string(subscribers) +
                        " subscribers and " + std::to_string(services) + " services";
  if (!failures.empty()) summary += "; not registered:" + failures;
  return summary;
}

void MasterWatch::run() {
  while (!stop_) {
    const double started = link::steadySeconds();
    std::string error;
    const std::optional<std::string> pid = pollPid(&error);
    MasterPresence::Change change;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      change = presence_.observe(link::steadySeconds(), pid);
    }
    if (change == MasterPresence::Change::kNewMaster) {
      const std::string summary = registerEverything();
      std::lock_guard<std::mutex> lock(mutex_);
      ++state_.registrations;
      state_.last_registration = summary;
    }
    if (pid && started >= next_service_refresh_) {
      rememberServices();
      next_service_refresh_ = started + service_refresh_;
      service_refresh_ = std::min(2.0 * service_refresh_, kServiceRefreshLast);
    }
    const double left = kPollPeriod - (link::steadySeconds() - started);
    if (left > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(left));
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
