"""Process helpers for make demo and the rviz test: free ports, a private ROS master, Xvfb,
screenshots, and stopping only what was started here (each child in its own process group,
stopped by its pid)."""
import os
import signal
import subprocess
import time

import with_free_ports  # same folder (scripts/)


def default_workspace():
    """The checkout's catkin workspace, by the one rule of scripts/setup/workspace_dir.sh."""
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "setup", "workspace_dir.sh")
    return subprocess.run([script], check=True, capture_output=True, text=True).stdout.strip()


def free_port():
    return with_free_ports.free_ports(1)[0]


def ros_env(setup_bash, master_port, ros_home):
    """The environment of `source setup_bash` with a private master and log folder."""
    out = subprocess.run(["bash", "-c", f"source '{setup_bash}' && env -0"], check=True, capture_output=True,
                         env=dict(os.environ, PATH="/usr/bin:" + os.environ.get("PATH", ""))).stdout
    env = dict(item.split("=", 1) for item in out.decode().split("\0") if "=" in item)
    env["PATH"] = "/usr/bin:" + env.get("PATH", "")
    env["ROS_MASTER_URI"] = f"http://localhost:{master_port}"
    env["ROS_HOME"] = ros_home
    env.pop("ROS_IP", None)
    env["ROS_HOSTNAME"] = "localhost"
    return env


def descendants(pid):
    """Every process below pid (children, grandchildren, ...), from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        children.setdefault(ppid, []).append(int(entry))
    out, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            out.append(child)
            todo.append(child)
    return out


class Processes:
    """Children started in their own process groups; stop() ends them newest first."""

    def __init__(self, log_dir):
        self.log_dir = log_dir
        self.children = []  # (name, Popen, log file)

    def start(self, name, args, env, console=False, **kwargs):
        """console: the child prints on this terminal (its stderr too) instead of logs/NAME.log."""
        log = open(os.path.join(self.log_dir, name + ".log"), "w")
        p = subprocess.Popen(args, env=env, stdout=None if console else log, stderr=None if console else subprocess.STDOUT,
                             start_new_session=True, **kwargs)
        self.children.append((name, p, log))
        return p

    def stop_one(self, p, sig=signal.SIGINT, timeout=15.0):
        # roslaunch starts each node in a session of its own: a node that outlives roslaunch
        # (killed after its timeout) is out of reach of the group signal, so every descendant
        # is noted first and killed if it is still there afterwards.
        family = descendants(p.pid) if p.poll() is None else []
        if p.poll() is None:
            try:
                os.killpg(p.pid, sig)  # the group this Popen created (start_new_session)
            except ProcessLookupError:
                pass
            try:
                p.wait(timeout)
            except subprocess.TimeoutExpired:
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                p.wait(5)
        for pid in family:
            try:
                os.kill(pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass

    def stop(self):
        for name, p, log in reversed(self.children):
            self.stop_one(p, signal.SIGTERM if name == "xvfb" else signal.SIGINT)
            log.close()
        self.children = []


def start_xvfb(procs, width=1280, height=800):
    """Xvfb on a free display (it picks the number itself); returns ':N'."""
    read_fd, write_fd = os.pipe()
    procs.start("xvfb", ["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{width}x{height}x24", "-nolisten",
                         "tcp"], env=dict(os.environ), pass_fds=(write_fd,))
    os.close(write_fd)
    number = b""
    deadline = time.time() + 30
    while time.time() < deadline and not number.endswith(b"\n"):
        chunk = os.read(read_fd, 16)
        if not chunk:
            break
        number += chunk
    os.close(read_fd)
    if not number.strip():
        raise RuntimeError("Xvfb did not start (see its log)")
    return ":" + number.decode().strip()


def start_master(procs, env, port, timeout=60.0):
    procs.start("roscore", ["roscore", "-p", str(port)], env)
    deadline = time.time() + timeout
    while time.time() < deadline:
        if subprocess.run(["rostopic", "list"], env=env, capture_output=True).returncode == 0:
            return
        time.sleep(0.3)
    raise RuntimeError(f"the ROS master on port {port} did not answer within {timeout:.0f} s")


def screenshot(display, path):
    """The whole X screen as PNG (imagemagick's convert by its full path)."""
    xwd = subprocess.run(["xwd", "-root", "-silent", "-display", display], check=True, capture_output=True).stdout
    subprocess.run(["/usr/bin/convert", "xwd:-", path], input=xwd, check=True)
