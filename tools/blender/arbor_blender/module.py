# Finding the `arbor` module: Blender's own Python path first, then the folder the add-on's preferences name,
# then $ARBOR_PYTHONPATH (os.pathsep-separated, like PYTHONPATH, which Blender ignores by default).
import importlib
import os
import sys


def _candidate_folders():
    folders = []
    try:
        import bpy

        addon = bpy.context.preferences.addons.get(__package__)
        if addon and addon.preferences and addon.preferences.module_path:
            folders.append(bpy.path.abspath(addon.preferences.module_path))
    except (AttributeError, ImportError):  # no preferences while the add-on is registered by hand (tests)
        pass
    folders += [f for f in os.environ.get("ARBOR_PYTHONPATH", "").split(os.pathsep) if f]
    return folders


def load():
    """The arbor module; raises ImportError saying where it was looked for."""
    try:
        return importlib.import_module("arbor")
    except ImportError as first:
        looked = []
        for folder in _candidate_folders():
            looked.append(folder)
            if folder not in sys.path:
                sys.path.insert(0, folder)
            try:
                return importlib.import_module("arbor")
            except ImportError:
                continue
        raise ImportError(
            f"the arbor Python module was not found ({first}); looked on Blender's Python path"
            + (" and in " + ", ".join(looked) if looked else "")
            + ". Build Arbor (cmake --build build --target arbor_python) and set the add-on's 'arbor module folder' "
            "to build/python, or $ARBOR_PYTHONPATH"
        ) from first


def status():
    try:
        arbor = load()
        return f"arbor {arbor.__version__} from {arbor.__file__}"
    except ImportError as error:
        return str(error)
