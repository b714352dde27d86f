"""What scripts/test/two_machines.py reads, each from inside the machine it belongs to (no probe
crosses the link): the emulators' ground truth (status socket: send a line, get
't x y theta v w motors open watchdog', as test/support/judge.h), the tracker emulator's
command journal ('t command v w'), and every node's per-connection byte counters (the ROS
slave API's getBusInfo / getBusStats, roscpp and rospy alike).
"""
import math
import socket
import threading
import time
import xmlrpc.client

from two_machines_net import entered

OFFSET = 0.3  # [m] the controlled point ahead of base_link (the URDF's control_point)


class Status:
    FIELDS = ("t", "x", "y", "theta", "v", "w", "motors", "open", "watchdog")

    def __init__(self, line):
        values = line.split()
        if len(values) != len(self.FIELDS):
            raise ValueError("status line %r" % line)
        for k, v in zip(self.FIELDS, values):
            setattr(self, k, float(v))

    def offset_point(self):
        return self.x + OFFSET * math.cos(self.theta), self.y + OFFSET * math.sin(self.theta)


class StatusSocket:
    """One emulator's status socket, opened inside its machine's namespace."""

    def __init__(self, ns, port):
        self.ns, self.port, self.sock, self.buf = ns, port, None, b""

    def query(self):
        """The emulator's Status, or None when it does not answer (then reconnects next time)."""
        try:
            if self.sock is None:
                with entered(self.ns):
                    self.sock = socket.create_connection(("127.0.0.1", self.port), timeout=1.0)
                self.buf = b""
            self.sock.sendall(b"\n")
            while b"\n" not in self.buf:
                chunk = self.sock.recv(512)
                if not chunk:
                    raise OSError("closed")
                self.buf += chunk
            line, self.buf = self.buf.split(b"\n", 1)
            return Status(line.decode())
        except (OSError, ValueError):
            if self.sock is not None:
                self.sock.close()
            self.sock = None
            return None


class PairRecorder:
    """Both robots' ground truth at 50 Hz on a thread of its own: (wall time, target, tracker,
    |target position - tracker's true offset point|), as test_two_robots.cpp's PairRecorder."""

    def __init__(self, target, tracker):
        self.target, self.tracker = target, tracker
        self.samples, self.lock, self.stopping = [], threading.Lock(), False
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        while not self.stopping:
            a, b = self.target.query(), self.tracker.query()
            if a and b:
                px, py = b.offset_point()
                with self.lock:
                    self.samples.append((time.monotonic(), a, b, math.hypot(a.x - px, a.y - py)))
            time.sleep(0.02)

    def last(self):
        with self.lock:
            return self.samples[-1] if self.samples else None

    def since(self, t0, t1=float("inf")):
        with self.lock:
            return [s for s in self.samples if t0 <= s[0] <= t1]

    def stop(self):
        self.stopping = True
        self.thread.join(timeout=2.0)


def read_command_log(path):
    """[(t, command, v, w)] of the emulator's journal."""
    out = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 4:
                out.append((float(fields[0]), fields[1], float(fields[2]), float(fields[3])))
    return out


def setpoint_pairs(commands, merge=0.02):
    """VEL and RVEL sent back to back are one setpoint pair (the later values, the first time)."""
    pairs = []
    for t, c, v, w in commands:
        if pairs and t - pairs[-1][0] < merge:
            pairs[-1] = (pairs[-1][0], v, w)
        else:
            pairs.append((t, v, w))
    return pairs


class _Transport(xmlrpc.client.Transport):
    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = 2.0  # a node that hangs must not hang the harness
        return connection


class Graph:
    """The ROS graph as the master knows it: node -> (slave URI, machine)."""

    def __init__(self, machines, master_machine, master_uri):
        self.machines, self.nodes = machines, {}
        self.master_machine, self.master_uri = master_machine, master_uri
        with entered(machines.ns[master_machine]):
            master = xmlrpc.client.ServerProxy(master_uri, transport=_Transport())
            _, _, state = master.getSystemState("/two_machines")
            names = sorted({n for kind in state for _, ns in kind for n in ns})
            for n in names:
                code, _, uri = master.lookupNode("/two_machines", n)
                if code == 1:
                    host = uri.split("//", 1)[1].rsplit(":", 1)[0]
                    self.nodes[n] = (uri, machines.machine_of(host))

    def topic_types(self):
        with entered(self.machines.ns[self.master_machine]):
            _, _, types = xmlrpc.client.ServerProxy(self.master_uri, transport=_Transport()).getTopicTypes("/two_machines")
        return dict(types)

    def call(self, node, method, *args):
        uri, machine = self.nodes[node]
        with entered(self.machines.ns[machine]):
            return getattr(xmlrpc.client.ServerProxy(uri, transport=_Transport()), method)("/two_machines", *args)

    def pids(self):
        """node -> pid (the slave API's getPid), for "nothing died"."""
        out = {}
        for n in self.nodes:
            try:
                code, _, pid = self.call(n, "getPid")
                out[n] = pid if code == 1 else None
            except (OSError, xmlrpc.client.Error):
                out[n] = None
        return out

    def traffic(self):
        """{(topic, from machine, to machine, publisher, subscriber): [bytes, messages] sent so far} over every
        publisher's connection to a subscriber on another machine (the publisher's counters:
        roscpp's [id, bytes, data bytes, messages, 0], rospy's [id, bytes, messages, alive])."""
        totals = {}
        for n, (_, machine) in self.nodes.items():
            try:
                _, _, info = self.call(n, "getBusInfo")
                stats = self.call(n, "getBusStats")
                # rospy answers [1, '', [pub, sub, srv]]; roscpp (Noetic) [pub, sub] alone
                # (its callback fills the result with the stats themselves).
                stats = stats[2] if len(stats) == 3 and stats[0] == 1 and isinstance(stats[1], str) else stats
            except (OSError, xmlrpc.client.Error):
                continue
            peers = {}  # (topic, connection id) -> subscriber, for outbound connections
            for conn in info:
                if len(conn) >= 5 and conn[2] == "o":
                    peers[(conn[4], conn[0])] = conn[1]
            for pub in stats[0] if stats else []:
                topic, conns = pub[0], pub[-1]
                for c in conns if isinstance(conns, list) else []:
                    subscriber = peers.get((topic, c[0]))
                    peer = self.nodes.get(subscriber, (None, None))[1]
                    if peer and peer != machine:
                        key = (topic, machine, peer, n, subscriber)
                        total = totals.setdefault(key, [0, 0])
                        total[0] += int(c[1])
                        total[1] += int(c[3] if len(c) >= 5 else c[2])
        return totals


def rates(before, after, seconds):
    """{(topic, from, to, publisher, subscriber): (bytes/s, messages/s)} between two traffic() snapshots."""
    out = {}
    for k, (b, m) in after.items():
        b0, m0 = before.get(k, (0, 0))
        if b > b0:
            out[k] = ((b - b0) / seconds, (m - m0) / seconds)
    return out
