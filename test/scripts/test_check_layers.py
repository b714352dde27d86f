#!/usr/bin/python3
"""check_layers.py on temporary trees: a bad include fails naming the file and the include.

Usage: test_check_layers.py PATH/TO/check_layers.py
"""
import os
import tempfile
import unittest

from script_loader import load_script_from_argv

check_layers = load_script_from_argv("check_layers")


class CheckLayers(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        self.write("include/amigobot_tracking/core/support/unit.h", "#include <Eigen/Dense>\n#include <vector>\n")
        self.write("src/core/support/unit.cpp", '#include "amigobot_tracking/core/support/unit.h"\n#include <cmath>\n')
        self.write("src/ros/node.cpp", "#include <ros/ros.h>\n#include \"amigobot_tracking/sim/scenario.h\"\n")

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, relative, text):
        path = os.path.join(self.root, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)

    def only_violation(self):
        """The one violation the tree must have."""
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual(len(messages), 1, messages)
        return messages[0]

    def test_clean_tree_passes_and_counts_every_include(self):
        messages, includes, files = check_layers.violations(self.root)
        self.assertEqual(messages, [])
        self.assertEqual((includes, files), (6, 3))

    def test_a_core_concern_includes_only_those_below_it(self):
        self.write("src/core/law/law.cpp", '#include "amigobot_tracking/core/support/unit.h"\n'
                   '#include "amigobot_tracking/core/supervision/loop.h"\n')
        self.assertIn('src/core/law/law.cpp:2: "amigobot_tracking/core/supervision/loop.h" (core/supervision) is not '
                      "allowed in core/law (allowed: robot, support)", self.only_violation())

    def test_supervision_may_include_every_other_concern(self):
        self.write("src/core/supervision/loop.cpp", "".join(
            f'#include "amigobot_tracking/core/{c}/x.h"\n' for c in ("support", "robot", "reference", "law", "perception")))
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual(messages, [])

    def test_a_core_file_outside_a_concern_folder_is_named(self):
        self.write("src/core/loose.cpp", '#include "amigobot_tracking/core/support/unit.h"\n')
        self.assertIn("src/core/loose.cpp:1:", self.only_violation())
        self.assertIn("core files live in a concern folder", self.only_violation())

    def test_ros_in_core_names_the_file_line_and_include(self):
        self.write("src/core/bad.cpp", "#include <cmath>\n#include <ros/ros.h>\n")
        self.assertIn("src/core/bad.cpp:2: <ros/ros.h> (other) is not allowed in layer core", self.only_violation())

    def test_sim_may_not_include_aria_nor_mrpt(self):
        self.write("include/amigobot_tracking/sim/x.h",
                   '#include "amigobot_tracking/aria/client.h"\n#include <mrpt/comms/CClientTCPSocket.h>\n'
                   "#include <yaml-cpp/yaml.h>\n#include <nlohmann/json.hpp>\n")
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual([m.split(" (")[0] for m in messages],
                         ['include/amigobot_tracking/sim/x.h:1: "amigobot_tracking/aria/client.h"',
                          "include/amigobot_tracking/sim/x.h:2: <mrpt/comms/CClientTCPSocket.h>"])

    def test_sim_mrpt_may_use_mrpt_sim_and_world_but_not_ros_and_sim_not_sim_mrpt(self):
        self.write("src/sim_mrpt/law.cpp", '#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>\n'
                   '#include "amigobot_tracking/sim/closed_loop.h"\n#include "amigobot_tracking/world/raycast.h"\n'
                   "#include <ros/ros.h>\n")
        self.write("src/sim/uses_peer.cpp", '#include "amigobot_tracking/sim_mrpt/reactive_law.h"\n')
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual([m.split(" (")[0] for m in messages],
                         ['src/sim/uses_peer.cpp:1: "amigobot_tracking/sim_mrpt/reactive_law.h"',
                          "src/sim_mrpt/law.cpp:4: <ros/ros.h>"])

    def test_aria_may_use_posix_and_world_but_core_may_not(self):
        self.write("src/aria/serial.cpp", '#include <termios.h>\n#include <sys/socket.h>\n'
                   '#include "amigobot_tracking/world/world.h"\n')
        self.write("src/core/posix.cpp", "#include <unistd.h>\n")
        self.assertTrue(self.only_violation().startswith("src/core/posix.cpp:1: <unistd.h> (posix)"))

    def test_teleop_may_use_termios_and_linux_headers_but_not_ros_nor_aria(self):
        self.write("src/teleop/device.cpp", "#include <termios.h>\n#include <linux/joystick.h>\n"
                   '#include "amigobot_tracking/core/support/types.h"\n#include "amigobot_tracking/aria/client.h"\n')
        self.write("src/core/joystick.cpp", "#include <linux/joystick.h>\n")
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual([m.split(" is not")[0] for m in messages],
                         ["src/core/joystick.cpp:1: <linux/joystick.h> (linux)",
                          'src/teleop/device.cpp:4: "amigobot_tracking/aria/client.h" (aria)'])

    def test_link_may_use_posix_only_and_aria_sensors_may_use_link(self):
        self.write("src/link/serial_port.cpp", "#include <termios.h>\n#include <sys/socket.h>\n#include <string>\n"
                   '#include "amigobot_tracking/core/support/types.h"\n#include <mrpt/comms/CSerialPort.h>\n#include <ros/ros.h>\n')
        self.write("src/aria/transport.cpp", '#include "amigobot_tracking/link/address.h"\n')
        self.write("src/sensors/device.cpp", '#include "amigobot_tracking/link/serial_port.h"\n')
        self.write("src/core/uses_link.cpp", '#include "amigobot_tracking/link/address.h"\n')
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual([m.split(" is not")[0] for m in messages],
                         ['src/core/uses_link.cpp:1: "amigobot_tracking/link/address.h" (link)',
                          'src/link/serial_port.cpp:4: "amigobot_tracking/core/support/types.h" (core)',
                          "src/link/serial_port.cpp:5: <mrpt/comms/CSerialPort.h> (mrpt)",
                          "src/link/serial_port.cpp:6: <ros/ros.h> (other)"])

    def test_relative_quoted_include_outside_ros_fails(self):
        self.write("src/world/world.cpp", '#include "world.h"\n')
        self.assertIn('"world.h" (other)', self.only_violation())

    def test_localization_may_use_mrpt_yaml_and_world_but_not_ros_nor_sensors(self):
        self.write("src/localization/localizer.cpp",
                   '#include <mrpt/slam/CICP.h>\n#include <yaml-cpp/yaml.h>\n#include "amigobot_tracking/world/world.h"\n'
                   '#include "amigobot_tracking/sensors/laser_driver.h"\n#include <tf2_ros/buffer.h>\n')
        messages, _, _ = check_layers.violations(self.root)
        self.assertEqual([m.split(" (")[0] for m in messages],
                         ['src/localization/localizer.cpp:4: "amigobot_tracking/sensors/laser_driver.h"',
                          "src/localization/localizer.cpp:5: <tf2_ros/buffer.h>"])

    def test_tools_may_not_include_ros(self):
        self.write("src/tools/tool.cpp", '#include <CLI/CLI.hpp>\n#include "amigobot_tracking/ros/conversions.h"\n')
        self.assertIn("src/tools/tool.cpp:2:", self.only_violation())


if __name__ == "__main__":
    unittest.main()
