"""Loads a script of scripts/ as a module from the path the test is given (CMake passes it)."""
import importlib.util
import sys


def load_script_from_argv(module_name):
    """The module at sys.argv[1]; removes that argument so unittest.main sees only its own."""
    if len(sys.argv) < 2 or not sys.argv[1].endswith(".py"):
        sys.exit(f"usage: {sys.argv[0]} PATH/TO/{module_name}.py [unittest args]")
    spec = importlib.util.spec_from_file_location(module_name, sys.argv.pop(1))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
