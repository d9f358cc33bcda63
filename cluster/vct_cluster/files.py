"""Atomic writes (temporary name + rename, as every vct output): a killed client leaves either
the whole file or none, so a rerun can trust what it finds."""
import json
import os


def write_bytes_atomically(path, data):
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)


def write_json_atomically(path, obj):
    write_bytes_atomically(path, (json.dumps(obj, indent=1, sort_keys=True) + "\n").encode())


def read_json(path, default=None):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return default
