#!/usr/bin/python3
"""The ROS master killed while tracking, then started again on the same port, in `make test`.

Starts its own roscore on a free port and test/e2e/master_restart.launch (the emulated robot,
driver, tracking on the circle reference), then judges from the emulator's ground truth and
its command journal, never from the stack's own messages:

  hang      the master SIGSTOPped 2 s while tracking (a busy master, the same one after): zero
            on the wire within HANG_BOUND, nothing non-zero while it hangs; after SIGCONT the
            motors come on and the robot tracks again by itself, with no service called
  stop      the master SIGKILLed while tracking (roscore with it): zero on the robot's wire and
            the motors off within BOUND; no non-zero setpoint on the wire after that while
            nobody enabled the motors
  services  a new roscore on the same port: /disable_motors and /enable_motors answer again
  standalone the stand-alone helper nodes (reference_publisher, sim_laser,
            ground_truth_localization, the trail publishers) are known to the new master, and
            a new subscriber receives ground_truth_localization's `ground_truth` and sim_laser's `scan`
  cmd_vel   a new cmd_vel publisher (rostopic pub) drives the robot after enable_motors
  tracking  /tracking/enable: the robot tracks again

Usage: master_restart.py [--logs DIR]  (a built, sourced workspace). Exit 0 when every case
passes; prints every figure. Kills only the processes it started.
"""
import argparse
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
import xmlrpc.client

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from with_free_ports import free_ports  # noqa: E402

MASTER_TIMEOUT = 0.5  # [s] config/driver.yaml
# master_timeout + the watch's poll period (0.1 s) + the driver's check period (0.1 s) + its
# next command slot (0.05 s) + 0.15 s of scheduling on a loaded 2-core machine
BOUND = MASTER_TIMEOUT + 0.4
# A hung master refuses nothing: each poll waits out its call timeout (0.3 s), and the second
# unanswered one in a row is the loss, 0.8 s at most after its last answer; then as above.
HANG_BOUND = 2 * 0.3 + 0.2 + 0.4
HANG_S = 2.0  # [s] the master stays stopped
MOVING = 0.05  # [m/s] true speed that counts as driving
# The stand-alone programs of the stack (not nodelets) master_restart.launch starts.
STANDALONE = ("/reference_publisher", "/sim_laser", "/ground_truth_localization", "/robot_trail", "/target_trail")
LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "test", "e2e", "master_restart.launch")


class Failed(Exception):
    pass


def truth(port):
    """The emulator's status line: t x y theta v w motors open watchdog."""
    with socket.create_connection(("127.0.0.1", port), timeout=2.0) as s:
        s.sendall(b"\n")
        data = b""
        while b"\n" not in data:
            chunk = s.recv(256)
            if not chunk:
                raise Failed("emulator status socket closed")
            data += chunk
    f = data.split(b"\n")[0].split()
    return {"t": float(f[0]), "v": float(f[4]), "w": float(f[5]), "motors": f[6] == b"1"}


def journal(path):
    """(t, v, w) of every motion command the emulator received."""
    rows = []
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) == 4:
                rows.append((float(p[0]), float(p[2]), float(p[3])))
    return rows


def master_pids(uri):
    """rosmaster's and rosout's pids: roscore starts them in sessions of their own, so killing
    roscore's group leaves them running."""
    master = xmlrpc.client.ServerProxy(uri)
    pids = [master.getPid("/master_restart")[2]]
    code, _, rosout_uri = master.lookupNode("/master_restart", "/rosout")
    if code == 1:
        pids.append(xmlrpc.client.ServerProxy(rosout_uri).getPid("/master_restart")[2])
    return pids


def truth_when_up(port):
    """truth(port), or None while the emulator's status socket is not listening yet (start-up)."""
    try:
        return truth(port)
    except ConnectionRefusedError:
        return None


def known_nodes(uri, names):
    """The nodes of `names` the master at uri can look up."""
    master = xmlrpc.client.ServerProxy(uri)
    try:
        return [n for n in names if master.lookupNode("/master_restart", n)[0] == 1]
    except (OSError, xmlrpc.client.Error):
        return []


def wait_until(predicate, timeout, period=0.05):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(period)
    return predicate()


class Run:
    def __init__(self, env, log_dir):
        self.env, self.log_dir, self.procs, self.roscore = env, log_dir, [], None

    def start(self, name, args):
        log = open(os.path.join(self.log_dir, name + ".log"), "ab")
        p = subprocess.Popen(args, env=self.env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        self.procs.append(p)
        return p

    def ros(self, args, timeout=5.0):
        """A ROS command line tool; (exit code, output)."""
        try:
            r = subprocess.run(args, env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                               text=True)
            return r.returncode, r.stdout.strip()
        except subprocess.TimeoutExpired:
            return -1, "timed out after %.0f s" % timeout

    def call(self, service, timeout=8.0):
        code, out = self.ros(["rosservice", "call", service], timeout)
        if code != 0:
            print("master_restart: rosservice call %s: %s" % (service, out.splitlines()[-1] if out else code), flush=True)
        return code == 0

    def kill_master(self, roscore, sig=signal.SIGKILL):
        """rosmaster, rosout and roscore itself."""
        try:
            pids = master_pids(self.env["ROS_MASTER_URI"])
        except (OSError, xmlrpc.client.Error):
            pids = []
        for pid in pids:
            try:
                os.kill(pid, sig)
            except ProcessLookupError:
                pass
        self.kill(roscore, sig)

    @staticmethod
    def kill(p, sig=signal.SIGKILL):
        if p.poll() is None:
            try:
                os.killpg(p.pid, sig)
            except ProcessLookupError:
                pass
        try:
            p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)

    def cleanup(self):
        for p in reversed(self.procs):  # the stack first, while its master still answers
            if "roscore" not in p.args:
                self.kill(p, signal.SIGINT)
        if self.roscore:
            self.kill_master(self.roscore, signal.SIGINT)
        for p in self.procs:
            self.kill(p, signal.SIGINT)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--logs", default=None, help="folder for the processes' output")
    args = parser.parse_args()
    master_port, tcp_port, status_port = free_ports(3)
    log_dir = args.logs or tempfile.mkdtemp(prefix="master_restart_")
    os.makedirs(log_dir, exist_ok=True)
    command_log = os.path.join(log_dir, "commands.txt")
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % master_port, ROS_HOSTNAME="127.0.0.1",
               PATH="/usr/bin:" + os.environ.get("PATH", ""))
    env.pop("ROS_IP", None)
    # A private log folder: roscore first sums up the size of the whole log folder, which on a
    # shared ~/.ros takes tens of seconds.
    env["ROS_LOG_DIR"] = os.path.join(log_dir, "ros_log")
    run = Run(env, log_dir)
    failures = []

    def check(case, ok, text):
        print("master_restart: %s: %s%s" % (case, "ok: " if ok else "FAILED: ", text), flush=True)
        if not ok:
            failures.append(case)

    try:
        master = run.roscore = run.start("roscore1", ["roscore", "-p", str(master_port)])
        if not wait_until(lambda: run.ros(["rosparam", "get", "/run_id"], 2.0)[0] == 0, 30.0, 0.5):
            raise Failed("roscore did not start")
        run.start("stack", ["roslaunch", LAUNCH, "tcp_port:=%d" % tcp_port, "status_port:=%d" % status_port,
                            "command_log:=" + command_log])
        if not wait_until(lambda: os.path.exists(command_log)
                          and (truth_when_up(status_port) or {"v": 0.0})["v"] > MOVING, 90.0, 0.5):
            raise Failed("the robot never tracked (see %s)" % log_dir)
        time.sleep(2.0)
        standalone = known_nodes(env["ROS_MASTER_URI"], STANDALONE)

        # hang: the same master stops answering for HANG_S, then answers again.
        rosmaster = master_pids(env["ROS_MASTER_URI"])[0]
        print("master_restart: tracking at %.2f m/s; stopping the master %.0f s" % (truth(status_port)["v"], HANG_S),
              flush=True)
        os.kill(rosmaster, signal.SIGSTOP)
        hung = truth(status_port)["t"]
        time.sleep(HANG_S)
        os.kill(rosmaster, signal.SIGCONT)
        resumed = truth(status_port)["t"]
        rows = journal(command_log)
        zero = next((r for r in rows if r[0] >= hung and r[1] == 0.0 and r[2] == 0.0), None)
        stop_s = zero[0] - hung if zero else float("inf")
        during = [r for r in rows if zero and zero[0] < r[0] <= resumed and (r[1] != 0.0 or r[2] != 0.0)]
        check("hang", stop_s <= HANG_BOUND, "zero on the wire %.3f s after the master stopped answering (bound %.2f s)"
              % (stop_s, HANG_BOUND))
        check("hang", not during, "%d non-zero setpoints on the wire while the master hung" % len(during))
        back = wait_until(lambda: truth(status_port)["motors"] and truth(status_port)["v"] > MOVING, 10.0)
        check("hang", back, "the same master back: motors %s, tracking again at %.3f m/s, no service called"
              % ("on" if truth(status_port)["motors"] else "off", truth(status_port)["v"]))
        time.sleep(2.0)

        before = truth(status_port)
        print("master_restart: tracking at %.2f m/s; killing the master" % before["v"], flush=True)
        run.kill_master(master)
        killed = truth(status_port)["t"]

        # stop: zero on the wire and motors off within BOUND, and nothing but zero afterwards.
        wait_until(lambda: not truth(status_port)["motors"], 3.0)
        time.sleep(2.0)
        rows = journal(command_log)
        zero = next((r for r in rows if r[0] >= killed and r[1] == 0.0 and r[2] == 0.0), None)
        stop_s = zero[0] - killed if zero else float("inf")
        after = [r for r in rows if zero and r[0] > zero[0] and (r[1] != 0.0 or r[2] != 0.0)]
        now = truth(status_port)
        check("stop", stop_s <= BOUND, "zero on the wire %.3f s after the master died (bound %.2f s)" % (stop_s, BOUND))
        check("stop", not after, "%d non-zero setpoints on the wire after the zero" % len(after))
        check("stop", not now["motors"] and abs(now["v"]) < 1e-3,
              "motors %s, true speed %.3f m/s 2 s later" % ("on" if now["motors"] else "off", now["v"]))

        # services: a new master on the same port; the stack registers with it by itself.
        restarted = time.monotonic()
        run.roscore = run.start("roscore2", ["roscore", "-p", str(master_port)])
        ok = wait_until(lambda: run.call("/disable_motors", 5.0), 30.0, 0.2)
        check("services", ok, "/disable_motors answered %.1f s after the new roscore started"
              % (time.monotonic() - restarted))
        check("services", not truth(status_port)["motors"], "the motors stayed off after the new master")
        check("services", run.call("/enable_motors") and wait_until(lambda: truth(status_port)["motors"], 3.0),
              "/enable_motors answered and the motors are on")

        # standalone: the helper programs registered with the new master too (their master watch).
        wait_until(lambda: known_nodes(env["ROS_MASTER_URI"], standalone) == standalone, 5.0, 0.2)
        again = known_nodes(env["ROS_MASTER_URI"], standalone)
        check("standalone", len(standalone) >= 3 and again == standalone,
              "%d of the %d stand-alone nodes known before the kill are known to the new master (%s)"
              % (len(again), len(standalone), " ".join(standalone)))
        for topic in ("/ground_truth", "/scan"):
            code, out = run.ros(["rostopic", "echo", "-n1", "--noarr", topic], 15.0)
            check("standalone", code == 0 and "header" in out, "a new subscriber to %s received a message%s"
                  % (topic, "" if code == 0 else ": " + (out.splitlines()[-1] if out else str(code))))

        # cmd_vel: tracking was disabled when the master died, so a new publisher is the only one.
        pub = run.start("cmd_vel", ["rostopic", "pub", "-r", "10", "/cmd_vel", "geometry_msgs/Twist",
                                    "{linear: {x: 0.1}}"])
        moved = wait_until(lambda: truth(status_port)["v"] > MOVING, 10.0)
        check("cmd_vel", moved, "a new cmd_vel publisher drives the robot (true speed %.3f m/s)"
              % truth(status_port)["v"])
        run.kill(pub, signal.SIGINT)
        time.sleep(1.5)  # the driver's command lock frees after 1 s of silence

        # tracking: enabled again through its service, the robot follows the target again.
        check("tracking", run.call("/tracking/enable"), "/tracking/enable answered")
        moving = wait_until(lambda: truth(status_port)["v"] > MOVING, 10.0)
        check("tracking", moving, "tracking drives again (true speed %.3f m/s)" % truth(status_port)["v"])
    except Failed as e:
        check("setup", False, str(e))
    finally:
        run.cleanup()
    print("master_restart: %s; logs in %s" % ("FAILED: " + ", ".join(sorted(set(failures))) if failures else "passed",
                                             log_dir), flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
