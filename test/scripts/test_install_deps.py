#!/usr/bin/python3
"""install_deps.sh's wait for the package manager's locks, on temporary lock files: a free lock
passes at once and silently; a lock held with flock (as flock(1)) or with fcntl (as apt and
dpkg take theirs) is waited for with a message naming the file and the holder's PID, and the
wait ends when it is released; a lock still held at the limit fails naming it.

Usage: test_install_deps.py PATH/TO/install_deps.sh
"""
import fcntl
import os
import subprocess
import sys
import tempfile
import time
import unittest

if len(sys.argv) < 2 or not sys.argv[1].endswith(".sh"):
    sys.exit(f"usage: {sys.argv[0]} PATH/TO/install_deps.sh [unittest args]")
SCRIPT = sys.argv.pop(1)


def wait_for_locks(locks, limit):
    """Runs wait_for_apt_locks on LOCKS in a bash that sourced the script: (exit code, output, s)."""
    env = dict(os.environ, AMIGOBOT_APT_LOCKS=" ".join(locks), AMIGOBOT_APT_LOCK_WAIT=str(limit),
               AMIGOBOT_APT_LOCK_POLL="1")
    start = time.monotonic()
    run = subprocess.run(["bash", "-c", f'source "{SCRIPT}" && wait_for_apt_locks'], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
    return run.returncode, run.stdout, time.monotonic() - start


class WaitForAptLocks(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.lock = os.path.join(self.dir.name, "lock-frontend")
        self.other = os.path.join(self.dir.name, "lock")
        for path in (self.lock, self.other):
            open(path, "w").close()

    def tearDown(self):
        self.dir.cleanup()

    def test_free_locks_pass_at_once_and_silently(self):
        code, out, took = wait_for_locks([self.lock, self.other, "/nonexistent/lock"], 10)
        self.assertEqual((code, out), (0, ""))
        self.assertLess(took, 5)

    def test_a_flock_holder_is_named_and_waited_for(self):
        holder = subprocess.Popen(["flock", self.other, "sleep", "3"])
        try:
            time.sleep(0.5)  # flock has the lock
            code, out, took = wait_for_locks([self.lock, self.other], 30)
        finally:
            holder.wait()
        self.assertEqual(code, 0, out)
        self.assertIn(f"waiting for {self.other}, held by PID {holder.pid} (flock)", out)
        self.assertIn("locks are free after", out)
        self.assertGreaterEqual(took, 2.0, "it returned before the holder let go")

    def test_an_fcntl_holder_as_apt_is_named_and_the_limit_fails(self):
        with open(self.lock, "w") as f:
            fcntl.lockf(f, fcntl.LOCK_EX)  # a POSIX record lock, as apt-get and dpkg take
            code, out, took = wait_for_locks([self.lock], 2)
        self.assertNotEqual(code, 0, out)
        self.assertIn(f"waiting for {self.lock}, held by PID {os.getpid()}", out)
        self.assertIn(f"{self.lock} is still held by PID {os.getpid()}", out)
        self.assertIn("after 2 s", out)


if __name__ == "__main__":
    unittest.main()
