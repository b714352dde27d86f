#!/usr/bin/python3
"""Runs a command (rostest) with one free TCP port per name appended as NAME:=PORT.

Usage: with_free_ports.py NAME [NAME ...] -- COMMAND [ARG ...]

The end-to-end .test files start amigobot_emulator on the ports named by their args
(tcp_port, status_port, ...); fixed ports would collide when two runs of the suite share a
machine, and the driver nodelet needs its port at load time, so the ports are chosen here,
just before rostest starts (as rostest itself chooses its master's port). Each port is bound
to a random port below the kernel's ephemeral range, released, and claimed for 15 min in
/tmp/amigobot_test_ports so that no other run hands it out meanwhile; the names get distinct ports.
"""
import os
import random
import socket
import sys
import time


def ephemeral_low(default=32768):
    """The lowest port the kernel hands out on its own (bind to 0, connect)."""
    try:
        with open("/proc/sys/net/ipv4/ip_local_port_range") as f:
            return int(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return default


CLAIMS = "/tmp/amigobot_test_ports"  # one file per port handed out lately, on this machine
CLAIM_LIFETIME = 900.0  # [s] longer than any rostest keeps its ports


def claim(port):
    """True when no other run of this script handed `port` out in the last CLAIM_LIFETIME s:
    between our check and the emulator's bind (seconds, more under load) the port is free again,
    and two runs side by side (make's -j2, or two checkouts) could otherwise both pick it; the
    loser's emulator then exits 1 with "cannot listen ... Address already in use"."""
    os.makedirs(CLAIMS, exist_ok=True)
    path = os.path.join(CLAIMS, str(port))
    try:
        os.close(os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
        return True
    except FileExistsError:
        try:
            if time.time() - os.path.getmtime(path) < CLAIM_LIFETIME:
                return False
            os.utime(path)  # a stale claim: ours now
            return True
        except OSError:
            return False


def free_ports(count):
    """count distinct free TCP ports, drawn below the ephemeral range: a port the kernel chose
    for bind(0) can be handed to another process's node or connection before our server binds
    it again (a master failed on that once when tests ran side by side); these are never
    handed out by the kernel, only by callers like this one, and each is checked by binding."""
    rng = random.SystemRandom()
    low, high = 20000, max(20001, ephemeral_low())
    sockets = []
    try:
        while len(sockets) < count:  # hold all of them until every one is chosen: distinct ports
            s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            port = rng.randrange(low, high)
            try:
                s.bind(("127.0.0.1", port))
            except OSError:
                s.close()
                continue
            if not claim(port):
                s.close()
                continue
            sockets.append(s)
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


def main(argv):
    if "--" not in argv or argv.index("--") == len(argv) - 1:
        sys.exit(__doc__)
    split = argv.index("--")
    names, command = argv[:split], argv[split + 1:]
    command += ["%s:=%d" % (name, port) for name, port in zip(names, free_ports(len(names)))]
    os.execvp(command[0], command)


if __name__ == "__main__":
    main(sys.argv[1:])
