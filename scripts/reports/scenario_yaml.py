"""Scenario variants for the reports (reproduce.py, beyond_paper.py): a shipped scenario file
read as data, changed key by key, and written back with python3-yaml, so an edit cannot miss
silently the way a text substitution can (a key that is not there raises KeyError)."""
import yaml


def load(path):
    with open(path) as f:
        return yaml.safe_load(f)


def write_data(data, dst):
    """Writes the scenario dict `data` to `dst`."""
    with open(dst, "w") as f:
        yaml.safe_dump(data, f, sort_keys=False, default_flow_style=None)
    return dst


def write_variant(src, dst, edit):
    """Writes to `dst` the scenario `src` after `edit(data)`, which changes the dict in place."""
    data = load(src)
    edit(data)
    return write_data(data, dst)


def set_key(data, dotted, value, must_exist=True):
    """data["a"]["b"] = value for dotted "a.b"; with must_exist, the key must be there already."""
    *sections, key = dotted.split(".")
    for section in sections:
        data = data[section]
    if must_exist and key not in data:
        raise KeyError(f"scenario has no {dotted}")
    data[key] = value
