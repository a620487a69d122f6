"""A config file read as plain data before anything evaluates it.

Snakemake's ``configfile:`` runs YTE templates (``__use_yte__: true``: Python expressions in the YAML)
while it loads the file.  Configs come from collaborators, so the Snakefile reads each file itself first,
with a safe YAML loader that never evaluates anything, and refuses templates and unknown top-level keys.
"""

from __future__ import annotations

import difflib
from pathlib import Path

from .schema import load_schema, load_yaml
from .errors import InputError

#: The key that asks Snakemake to evaluate a YAML file as a YTE template.
TEMPLATE_KEY = "__use_yte__"


def refuse_unsafe_config_files(paths) -> None:
    """One line for the first of ``paths`` (existing files) that is templated, not a mapping, or has a
    top-level key the schema does not know.  Nothing in the files is evaluated."""
    known = list(load_schema()["properties"])
    for path in paths:
        if not Path(path).is_file():
            continue  # Snakemake names a missing config file itself
        data = load_yaml(path)
        if data is None:
            continue
        if not isinstance(data, dict):
            raise InputError(f"the config must be a mapping of keys (results_dir, materials, ...), found a "
                             f"{type(data).__name__}", source=str(path))
        if TEMPLATE_KEY in data:
            raise InputError(f"config key {TEMPLATE_KEY}: templated configs (YTE) are refused, their expressions "
                             "would run as code; write plain values", source=str(path))
        unknown = [str(k) for k in data if k not in known]
        if unknown:
            close = difflib.get_close_matches(unknown[0], known, n=1)
            hint = f"; did you mean '{close[0]}'?" if close else f"; known: {', '.join(known)}"
            raise InputError(f"config key {unknown[0][:80]}: unknown top-level key{hint}", source=str(path))


def configfiles_on_command_line(argv: list[str]) -> list[str]:
    """The files after ``--configfile``/``--configfiles`` (several may follow one flag) in Snakemake's
    command line ``argv``."""
    files, taking = [], False
    for arg in argv:
        flag, eq, value = arg.partition("=")
        if flag in ("--configfile", "--configfiles"):
            taking = not eq
            if eq:
                files.append(value)
        elif arg.startswith("-"):
            taking = False
        elif taking:
            files.append(arg)
    return files


def refuse_unsafe_command_line() -> bool:
    """Called from the workflow's default profile (profiles/default), which Snakemake reads before it
    loads a ``--configfile``: exits with one line when such a file is templated or has unknown keys, so
    its expressions never run.  Returns False (the profile then sets nothing)."""
    import sys

    try:
        refuse_unsafe_config_files(configfiles_on_command_line(sys.argv[1:]))
    except InputError as err:
        sys.exit(f"demid: error: {err}")
    return False
