#!/usr/bin/python3
"""The commands the README and docs/ give a user are true of the code. Everything is read from
the docs' own text, so renaming a launch argument, a service or a topic fails this test:

- every `[roslaunch amigobot_tracking] FILE.launch NAME:=VALUE ...` in backticks or a code
  block: FILE exists, each NAME is an argument it declares, and (when no value is a
  placeholder such as `…`, `$HOME` or a file the user's own run writes) the configuration
  loads as roslaunch loads it (arguments, evals, parameters);
- every `rosservice call /SERVICE` is offered by the running sim.launch (docs_commands.test
  starts the README's quick start; `/tracker/...` and `/target/...` are the same nodes under the
  two-robot namespaces, checked without the namespace);
- no user doc cites an internal issue number; CHANGELOG.rst's newest version is package.xml's;
- every topic the docs tell the user to publish on (`publish on \`TOPIC\``, `rostopic pub
  TOPIC`) has a subscriber in that run.
"""
import glob
import os
import re
import sys
import time
import unittest
import xml.etree.ElementTree as ET

import rosgraph
import roslaunch.config
import roslaunch.xmlloader
import rospkg
import rospy
import rostest

PACKAGE = rospkg.RosPack().get_path("amigobot_tracking")

# Namespaces of two_robots.launch / amigobot.launch robot:=NAME: the same nodes as sim.launch's.
ROBOT_NAMESPACES = ("/tracker", "/target")
# A launch command: optional `roslaunch amigobot_tracking`, FILE.launch, then NAME:=VALUE words
# (across line breaks: the docs wrap long commands).
LAUNCH = re.compile(r"roslaunch\s+amigobot_tracking\s+([\w.]+\.launch)((?:\s+\w+:=[^\s`]*)*)"
                    r"|([\w.]+\.launch)((?:\s+\w+:=[^\s`]*)+)")
SERVICE_CALL = re.compile(r"rosservice call (/[\w/]+)")
PUBLISH = re.compile(r"publish\s+on\s+`(/?[\w/]+)`|rostopic\s+pub\s+(?:-\S+\s+)*(/[\w/]+)")
PLACEHOLDER = re.compile(r"…|\.\.\.|\$|<|[A-Z]{2,}_[A-Z]+")


def doc_files():
    return [os.path.join(PACKAGE, "README.md")] + sorted(glob.glob(os.path.join(PACKAGE, "docs", "*.md")))


def code_spans(text):
    """The text of every fenced or indented code block and every `...` span."""
    spans = re.findall(r"```.*?```", text, re.S)
    spans += re.findall(r"(?:^(?: {4}|\t).*\n?)+", text, re.M)
    spans += re.findall(r"`([^`]+)`", re.sub(r"```.*?```", "", text, flags=re.S))
    return spans


def doc_launch_commands():
    """(doc, launch file, [(name, value)]) of every launch command in the docs."""
    found = []
    for path in doc_files():
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for span in code_spans(text):
            for match in LAUNCH.findall(span):
                launch, args = (match[0], match[1]) if match[0] else (match[2], match[3])
                pairs = [tuple(word.split(":=", 1)) for word in args.split()]
                found.append((os.path.relpath(path, PACKAGE), launch, pairs))
    return found


def users_own_file(value):
    """A relative path that is not in the package: a file the user's own run writes
    (`tracking_params:=out/tune/tuned_gains.yaml`), not there to load here."""
    return "/" in value and not value.startswith("/") and not os.path.exists(os.path.join(PACKAGE, value))


def launch_path(name):
    """Where roslaunch finds FILE.launch in the package (it searches the whole package)."""
    for folder, _, files in os.walk(os.path.join(PACKAGE, "launch")):
        if name in files:
            return os.path.join(folder, name)
    return None


def load_problem(path, args):
    """Why the configuration does not load as roslaunch loads it (args, evals, parameters), or
    None. Without roscore.xml (its `rosversion` commands cost seconds); that the executables
    exist is make test's launch checks' part (scripts/test/check_launch.py)."""
    try:
        roslaunch.xmlloader.XmlLoader().load(path, roslaunch.config.ROSLaunchConfig(), argv=["roslaunch"] + args,
                                             verbose=False)
    except Exception as err:  # roslaunch raises several kinds; each names the element
        return str(err).splitlines()[0] if str(err) else type(err).__name__
    return None


def declared_args(launch_path):
    """Arguments a user may set: <arg> without value= (value= is fixed, not overridable)."""
    root = ET.parse(launch_path).getroot()
    return {a.get("name") for a in root.iter("arg") if a.get("value") is None and a in list(root)}


def docs_text():
    return {os.path.relpath(p, PACKAGE): open(p, encoding="utf-8").read() for p in doc_files()}


class DocsLaunchCommands(unittest.TestCase):
    """Static: no master needed (the launch files as the docs call them)."""

    def test_the_docs_have_launch_commands(self):
        commands = doc_launch_commands()
        self.assertGreaterEqual(len(commands), 10, "the extraction found too few launch commands in the docs")
        self.assertIn("sim.launch", {launch for _, launch, _ in commands})

    def test_no_internal_issue_numbers(self):
        found = [f"{doc}: {m.group(0)}" for doc, text in docs_text().items()
                 for m in re.finditer(r"\bissues? #?\d+", text, re.I)]
        self.assertEqual(found, [], "user docs cite the project's internal issue numbers")

    def test_the_changelog_names_the_package_version(self):
        from catkin_pkg.changelog import get_changelog_from_path
        from catkin_pkg.package import parse_package
        versions = [v for v, _, _ in get_changelog_from_path(os.path.join(PACKAGE, "CHANGELOG.rst")).foreach_version()]
        self.assertEqual(versions[:1], [parse_package(PACKAGE).version], "CHANGELOG.rst's newest version")

    def test_every_argument_the_docs_name_is_declared(self):
        problems = []
        for doc, launch, pairs in doc_launch_commands():
            path = launch_path(launch)
            if not path:
                problems.append(f"{doc}: {launch}: no such launch file")
                continue
            unknown = [name for name, _ in pairs if name not in declared_args(path)]
            if unknown:
                problems.append(f"{doc}: {launch}: no argument {', '.join(unknown)}")
        self.assertEqual(problems, [])

    def test_every_concrete_command_loads(self):
        problems, loaded, seen = [], 0, set()
        for doc, launch, pairs in doc_launch_commands():
            if any(PLACEHOLDER.search(value) or not value or users_own_file(value) for _, value in pairs):
                continue  # a placeholder: only the argument names are checked
            args = [f"{name}:={value}" for name, value in pairs]
            # rviz needs a display; the rviz check of make test opens the shipped display.
            args = [a for a in args if not a.startswith("rviz:=")]
            if (launch, tuple(args)) in seen:
                continue
            seen.add((launch, tuple(args)))
            loaded += 1
            problem = load_problem(launch_path(launch), args)
            if problem:
                problems.append(f"{doc}: `{launch} {' '.join(args)}`: {problem}")
        self.assertGreaterEqual(loaded, 5)
        self.assertEqual(problems, [])


class DocsCommands(DocsLaunchCommands):
    """And dynamic: sim.launch as the README's quick start runs it (docs_commands.test)."""

    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_docs_commands")
        cls.master = rosgraph.Master("/test_docs_commands")
        texts = docs_text()
        cls.services = {}
        for doc, text in texts.items():
            for name in SERVICE_CALL.findall(text):
                cls.services.setdefault(name, doc)
        cls.topics = {}
        for doc, text in texts.items():
            for backticked, piped in PUBLISH.findall(text):
                cls.topics.setdefault(backticked or piped, doc)

    def wait_for(self, what, names, timeout=40.0):
        """Names of `names` still missing from the master's `what` after timeout."""
        deadline = time.time() + timeout
        while True:
            publishers, subscribers, services = self.master.getSystemState()
            have = {"services": {s for s, _ in services}, "subscribers": {t for t, _ in subscribers}}[what]
            missing = [n for n in names if n not in have]
            if not missing or time.time() > deadline:
                return missing
            time.sleep(0.5)

    @staticmethod
    def without_robot_namespace(name):
        for ns in ROBOT_NAMESPACES:
            if name.startswith(ns + "/"):
                return name[len(ns):]
        return name

    def test_the_readme_names_the_quick_start_services(self):
        for name in ("/enable_motors", "/tracking/enable", "/localization/save_map"):
            self.assertIn(name, self.services, f"the docs no longer name {name}")

    def test_every_service_the_docs_call_exists(self):
        wanted = sorted({self.without_robot_namespace(n) for n in self.services})
        missing = self.wait_for("services", wanted)
        self.assertEqual([f"{n} (named in {self.services.get(n, 'a namespaced call')})" for n in missing], [])

    def test_every_topic_the_docs_publish_on_is_subscribed(self):
        self.assertTrue(self.topics, "the docs name no topic to publish on")
        wanted = sorted(n if n.startswith("/") else "/" + n for n in self.topics)
        missing = self.wait_for("subscribers", wanted)
        self.assertEqual(missing, [], f"topics the docs publish on that nothing subscribes: {missing}")


if __name__ == "__main__":
    rostest.rosrun("amigobot_tracking", "docs_commands", DocsCommands, sys.argv)
