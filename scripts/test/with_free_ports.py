#!/usr/bin/python3
"""Runs a command (rostest) with one free TCP port per name appended as NAME:=PORT.

Usage: with_free_ports.py NAME [NAME ...] -- COMMAND [ARG ...]

The end-to-end .test files start amigobot_emulator on the ports named by their args
(tcp_port, status_port, ...); fixed ports would collide when two runs of the suite share a
machine, and the driver nodelet needs its port at load time, so the ports are chosen here,
just before rostest starts (as rostest itself chooses its master's port). Each port is bound
to 0, read back and released; the names get distinct ports.
"""
import os
import random
import socket
import sys


def ephemeral_low(default=32768):
    """The lowest port the kernel hands out on its own (bind to 0, connect)."""
    try:
        with open("/proc/sys/net/ipv4/ip_local_port_range") as f:
            return int(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return default


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
            try:
                s.bind(("127.0.0.1", rng.randrange(low, high)))
            except OSError:
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
