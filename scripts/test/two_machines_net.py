"""Linux network namespaces standing in for computers, for scripts/test/two_machines.py.

Machines(tag, {"tracker": "10.213.21.2", "target": "10.213.21.3"}) makes one namespace per
computer (its own loopback, its own ports, its own address) joined by one veth pair, the
`wlan0` of each (the Wi-Fi between the two Odroids). Everything started with start() runs in
its machine's namespace; destroy() stops it and deletes the namespaces: every process in a
namespace of ours was started by us, so they are found by `ip netns pids` (roslaunch puts its
nodes in sessions of their own, out of reach of a process-group kill). Needs root and iproute2.
"""
import contextlib
import ctypes
import os
import re
import signal
import subprocess
import time

CLONE_NEWNET = 0x40000000
PREFIX = "am2m"  # namespaces am2m<harness pid>_<machine>
LINK = "wlan0"
_libc = ctypes.CDLL(None, use_errno=True)


def ip(*args, check=True, timeout=10):
    """Runs `ip ARGS`; raises RuntimeError naming the command and its complaint."""
    r = subprocess.run(["ip", *args], capture_output=True, text=True, timeout=timeout)
    if check and r.returncode != 0:
        raise RuntimeError("ip %s: %s" % (" ".join(args), r.stderr.strip() or "exit %d" % r.returncode))
    return r.stdout


@contextlib.contextmanager
def entered(ns):
    """The calling thread in namespace `ns` (sockets opened inside stay there after leaving)."""
    own = os.open("/proc/thread-self/ns/net", os.O_RDONLY)
    other = os.open("/run/netns/" + ns, os.O_RDONLY)
    try:
        if _libc.setns(other, CLONE_NEWNET) != 0:
            raise OSError(ctypes.get_errno(), "setns into " + ns)
        yield
    finally:
        _libc.setns(own, CLONE_NEWNET)
        os.close(own)
        os.close(other)


def pids_in(ns):
    r = subprocess.run(["ip", "netns", "pids", ns], capture_output=True, text=True, timeout=10)
    return [int(p) for p in r.stdout.split() if p.isdigit() and int(p) != os.getpid()]


def kill_all_in(ns, grace=3.0):
    """SIGTERM to every process in `ns`, SIGKILL to what is left after `grace` s."""
    for sig, wait in ((signal.SIGTERM, grace), (signal.SIGKILL, 2.0)):
        pids = pids_in(ns)
        for pid in pids:
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, sig)
        end = time.monotonic() + wait
        while pids and time.monotonic() < end:
            time.sleep(0.1)
            pids = pids_in(ns)
        if not pids:
            return 0
    return len(pids_in(ns))


def remove_stale():
    """Deletes namespaces a killed harness left (am2m<pid>_* whose pid is gone); their names."""
    gone = []
    for line in ip("netns", "list", check=False).splitlines():
        m = re.match(r"(%s(\d+)_\w+)" % PREFIX, line)
        if not m or os.path.exists("/proc/" + m.group(2)):
            continue
        kill_all_in(m.group(1), grace=1.0)
        ip("netns", "del", m.group(1), check=False)
        gone.append(m.group(1))
    return gone


class Machines:
    def __init__(self, hosts, prefix_len=24):
        self.hosts = dict(hosts)  # machine -> IPv4 address
        self.ns = {m: "%s%d_%s" % (PREFIX, os.getpid(), m) for m in hosts}
        self.prefix_len = prefix_len
        self.procs = []  # (machine, name, Popen, log file)

    def create(self):
        names = list(self.hosts)
        for m in names:
            ip("netns", "add", self.ns[m])
            ip("-n", self.ns[m], "link", "set", "lo", "up")
        a, b = names[0], names[1]
        ip("-n", self.ns[a], "link", "add", LINK, "type", "veth", "peer", "name", LINK, "netns", self.ns[b])
        for m in (a, b):
            ip("-n", self.ns[m], "addr", "add", "%s/%d" % (self.hosts[m], self.prefix_len), "dev", LINK)
            ip("-n", self.ns[m], "link", "set", LINK, "up")

    def machine_of(self, host):
        return next((m for m, a in self.hosts.items() if a == host), None)

    def set_link(self, up):
        """Both ends of the link up or down (carrier lost on both sides, as out of Wi-Fi range)."""
        for m in self.hosts:
            ip("-n", self.ns[m], "link", "set", LINK, "up" if up else "down")

    def counters(self, machine):
        """(rx bytes, tx bytes, rx packets, tx packets) of the machine's end of the link."""
        import json
        s = json.loads(ip("-n", self.ns[machine], "-s", "-j", "link", "show", LINK))[0]["stats64"]
        return s["rx"]["bytes"], s["tx"]["bytes"], s["rx"]["packets"], s["tx"]["packets"]

    def start(self, machine, name, cmd, env, log_dir):
        """Starts cmd in the machine's namespace, in a session of its own, output to a log."""
        log = open(os.path.join(log_dir, name + ".log"), "wb")
        p = subprocess.Popen(["ip", "netns", "exec", self.ns[machine], *cmd], env=env, stdout=log,
                             stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)
        self.procs.append((machine, name, p, log))
        return p

    def dead(self):
        """Names (and exit codes) of the processes started here that have exited."""
        return ["%s (exit %s)" % (name, p.returncode) for _, name, p, _ in self.procs if p.poll() is not None]

    def stop(self, grace=8.0):
        """SIGINT to each started process group (roslaunch stops its nodes), then the rest."""
        for _, _, p, _ in reversed(self.procs):
            if p.poll() is None:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(p.pid, signal.SIGINT)
        end = time.monotonic() + grace
        for _, _, p, _ in self.procs:
            with contextlib.suppress(subprocess.TimeoutExpired):
                p.wait(timeout=max(0.1, end - time.monotonic()))

    def destroy(self):
        """Stops everything in our namespaces and deletes them; a list of what went wrong."""
        problems = []
        for m, ns in self.ns.items():
            if not os.path.exists("/run/netns/" + ns):
                continue
            left = kill_all_in(ns)
            if left:
                problems.append("%d processes survived SIGKILL in %s" % (left, ns))
            r = subprocess.run(["ip", "netns", "del", ns], capture_output=True, text=True, timeout=10)
            if r.returncode != 0:
                problems.append("ip netns del %s: %s" % (ns, r.stderr.strip()))
        for _, _, p, log in self.procs:
            if p.poll() is None:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(p.pid, signal.SIGKILL)
            log.close()
        return problems
