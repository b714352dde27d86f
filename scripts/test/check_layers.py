#!/usr/bin/python3
"""Fails when a layer's source includes what the layer may not use.

Usage: check_layers.py SOURCE_DIR
A layer is the folder include/amigobot_tracking/<layer>/ together with src/<layer>/ (and
their subfolders); src/tools holds the ROS-free command-line tools. Every #include of every
file there is sorted into a kind (the package's own layers by their folder, the C++ standard
library, POSIX, Eigen, yaml-cpp, ...) and checked against the table below; the ros layer may
use anything. Prints `file:line: <include> (kind) is not allowed in layer L` for each
violation and exits 1; exits 0 naming how many includes of how many files it checked.
"""
import os
import re
import sys

# What each layer may include, besides itself.
ALLOWED = {
    "core": {"std", "eigen"},
    "sim": {"std", "eigen", "core", "yaml", "json"},
    "sim_mrpt": {"std", "eigen", "core", "world", "sim", "mrpt"},
    "world": {"std", "eigen", "core", "yaml"},
    # The byte links (host:port, serial opener, emulator sockets and pty): below every device
    # layer and beside core, so it depends on nothing of the package (and needs no MRPT).
    "link": {"std", "posix"},
    "aria": {"std", "posix", "eigen", "core", "world", "link", "mrpt", "yaml"},
    "sensors": {"std", "posix", "eigen", "core", "world", "link", "mrpt"},
    "localization": {"std", "eigen", "core", "world", "mrpt", "yaml"},
    "teleop": {"std", "posix", "linux", "eigen", "core"},
    "tools": {"std", "posix", "eigen", "core", "sim", "sim_mrpt", "link", "aria", "sensors", "localization", "world", "mrpt", "yaml", "json", "cli11"},
    "ros": None,  # anything
}
# Inside core, each folder is a concern, and a concern includes only those below it: support
# (types, field tables, files, arguments) <- robot (its limits, diamond, kinematics) and
# reference (the target's trajectory) <- law (the control laws and their parts) and perception
# (obstacles from scans and virtual disks) <- supervision (staleness, locks, the loop).
CORE_ALLOWED = {
    "support": set(),
    "robot": {"support"},
    "reference": {"support"},
    "law": {"support", "robot"},
    "perception": {"support", "robot"},
    "supervision": {"support", "robot", "reference", "law", "perception"},
}
LIBRARIES = {"Eigen": "eigen", "yaml-cpp": "yaml", "nlohmann": "json", "mrpt": "mrpt", "CLI": "cli11",
             "linux": "linux"}  # linux: the kernel's user-space API headers (linux/joystick.h)
POSIX_FOLDERS = {"sys", "netinet", "arpa"}
STD = set("""
algorithm any array atomic bitset cassert cctype cerrno cfloat charconv chrono cinttypes climits
clocale cmath complex condition_variable csetjmp csignal cstdarg cstddef cstdint cstdio cstdlib
cstring ctime cwchar deque exception execution filesystem forward_list fstream functional future
initializer_list iomanip ios iosfwd iostream istream iterator limits list locale map memory
memory_resource mutex new numeric optional ostream queue random ratio regex scoped_allocator set
shared_mutex sstream stack stdexcept streambuf string string_view system_error thread tuple
type_traits typeindex typeinfo unordered_map unordered_set utility valarray variant vector
""".split())
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc")


def kind_of(bracket, path):
    """The kind of one include: a layer name, a library, 'std', 'posix' or 'other'."""
    parts = path.split("/")
    if parts[0] == "amigobot_tracking" and len(parts) > 2:
        return parts[1] if parts[1] in ALLOWED else "other"
    if bracket == '"':
        return "other"  # the package's own headers are included by their full path
    if len(parts) == 1:
        if path in STD:
            return "std"
        return "posix" if path.endswith(".h") else "other"
    if parts[0] in POSIX_FOLDERS:
        return "posix"
    return LIBRARIES.get(parts[0], "other")


def core_concern(path):
    """The concern folder of a core file or include path ('support', 'law', ...), or None."""
    parts = path.replace(os.sep, "/").split("/")
    for i in range(len(parts) - 2):
        if parts[i] == "core" and parts[i + 1] in CORE_ALLOWED:
            return parts[i + 1]
    return None


def layer_files(root):
    """(layer, path) of every source file of every layer folder that exists."""
    for layer in ALLOWED:
        for base in (os.path.join(root, "include", "amigobot_tracking", layer), os.path.join(root, "src", layer)):
            for folder, _, names in os.walk(base):
                for name in sorted(names):
                    if name.endswith(SOURCE_SUFFIXES):
                        yield layer, os.path.join(folder, name)


def violations(root):
    """(messages, includes checked, files checked) for the tree at root."""
    messages, includes, files = [], 0, 0
    for layer, path in layer_files(root):
        files += 1
        allowed = ALLOWED[layer]
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                includes += 1
                kind = kind_of(match.group(1), match.group(2))
                shown = f"{match.group(1)}{match.group(2)}{'>' if match.group(1) == '<' else chr(34)}"
                if allowed is not None and kind != layer and kind not in allowed:
                    messages.append(f"{os.path.relpath(path, root)}:{number}: {shown} ({kind}) is not allowed "
                                    f"in layer {layer} (allowed: {', '.join(sorted(allowed))})")
                if layer == "core" and kind == "core":
                    concern, used = core_concern(os.path.relpath(path, root)), core_concern(match.group(2))
                    if concern is None or used is None:
                        messages.append(f"{os.path.relpath(path, root)}:{number}: {shown}: core files live in a "
                                        f"concern folder ({', '.join(CORE_ALLOWED)})")
                    elif used != concern and used not in CORE_ALLOWED[concern]:
                        messages.append(f"{os.path.relpath(path, root)}:{number}: {shown} (core/{used}) is not "
                                        f"allowed in core/{concern} (allowed: "
                                        f"{', '.join(sorted(CORE_ALLOWED[concern])) or 'nothing else in core'})")
    return messages, includes, files


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    if not os.path.isdir(os.path.join(root, "include", "amigobot_tracking")):
        sys.exit(f"check_layers: {root} has no include/amigobot_tracking folder")
    messages, includes, files = violations(root)
    for message in messages:
        print(message)
    if messages:
        sys.exit(f"check_layers: {len(messages)} include(s) cross a layer boundary")
    print(f"check_layers: {includes} includes in {files} files respect the layers")


if __name__ == "__main__":
    main()
