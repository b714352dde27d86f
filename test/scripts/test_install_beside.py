#!/usr/bin/python3
"""install_beside.sh (make demo: the desktop packages install while the demo compiles), with a
stand-in for install_deps.sh that takes 2 s: the command and the install run at the same time;
the script waits for the install even when the command failed; a failed install fails the step
naming its log; with nothing missing no install starts.

Usage: test_install_beside.py PATH/TO/install_beside.sh
"""
import os
import stat
import subprocess
import sys
import tempfile
import time
import unittest

if len(sys.argv) < 2 or not sys.argv[1].endswith(".sh"):
    sys.exit(f"usage: {sys.argv[0]} PATH/TO/install_beside.sh [unittest args]")
SCRIPT = sys.argv.pop(1)

# install_deps.sh's two behaviours that install_beside.sh uses: LIST --check (exit 1 and a line
# when packages are missing) and LIST (install: here 2 s, then a marker file and FAKE_RC).
FAKE = """#!/bin/bash
if [ "${2:-}" = --check ]; then
  [ "$FAKE_MISSING" = yes ] || { echo "deps: all 7 Debian packages present"; exit 0; }
  echo "deps: 2 of 7 missing (fake.txt): rviz xvfb"; exit 1
fi
sleep 2
echo "installed by $1" > "$FAKE_MARKER"
echo "0 upgraded, 2 newly installed, 0 to remove"
echo "Setting up rviz (fake)"
exit $FAKE_RC
"""


class InstallBeside(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.fake = os.path.join(self.dir.name, "install_deps.sh")
        with open(self.fake, "w") as f:
            f.write(FAKE)
        os.chmod(self.fake, os.stat(self.fake).st_mode | stat.S_IXUSR)
        self.marker = os.path.join(self.dir.name, "installed")
        self.log = os.path.join(self.dir.name, "logs", "deps_desktop.log")

    def tearDown(self):
        self.dir.cleanup()

    def run_beside(self, command, missing="yes", install_rc=0):
        env = dict(os.environ, AMIGOBOT_INSTALL_DEPS=self.fake, FAKE_MISSING=missing, FAKE_MARKER=self.marker,
                   FAKE_RC=str(install_rc))
        start = time.monotonic()
        run = subprocess.run([SCRIPT, "--desktop", self.log, "--", "bash", "-c", command], env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=30)
        return run.returncode, run.stdout, time.monotonic() - start

    def test_the_command_and_the_install_overlap(self):
        code, out, seconds = self.run_beside("sleep 2; echo built")
        self.assertEqual(code, 0, out)
        self.assertIn("built", out)
        self.assertTrue(os.path.exists(self.marker), out)
        self.assertLess(seconds, 3.5, "2 s + 2 s ran one after the other: " + out)
        self.assertIn(self.log, out)  # where the install's output went
        self.assertIn("2 newly installed", out)  # apt's count, summed up at the end

    def test_a_failed_command_keeps_its_code_after_the_install_ends(self):
        code, out, _ = self.run_beside("exit 7")
        self.assertEqual(code, 7, out)
        self.assertTrue(os.path.exists(self.marker), "returned before the install ended: " + out)

    def test_a_failed_install_fails_the_step_naming_its_log(self):
        code, out, _ = self.run_beside("echo built", install_rc=100)
        self.assertEqual(code, 1, out)
        self.assertIn("failed (exit 100)", out)
        self.assertIn(self.log, out)

    def test_nothing_missing_starts_no_install(self):
        code, out, seconds = self.run_beside("exit 3", missing="no")
        self.assertEqual(code, 3, out)
        self.assertFalse(os.path.exists(self.marker), out)
        self.assertLess(seconds, 1.5, out)


if __name__ == "__main__":
    unittest.main()
