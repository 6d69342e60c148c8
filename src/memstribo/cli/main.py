# PYTHON_ARGCOMPLETE_OK
"""Entry point of the ``memstribo`` command: option parsing, parameters, errors, output."""

from __future__ import annotations

import argparse
import importlib
import os
import pkgutil
import re
import sys
from types import ModuleType

from memstribo import __version__
from memstribo.errors import MemstriboError
from memstribo.output import dumps_json

EXIT_USAGE = 2

DESCRIPTION = """\
Friction, adhesion, stiction and coating wear between the teeth of silicon MEMS
microgears, from their measured nanoscale roughness (all results in SI units).
"""

EPILOG = """\
Every model parameter can be changed with --set NAME=VALUE (values may carry units:
--set normal_load="50 uN") or a TOML file (--config FILE); 'memstribo parameters' lists
them with their defaults and sources. Add --json for one JSON object of SI values.
"""


def _command_modules() -> list[ModuleType]:
    package = importlib.import_module(__package__)
    modules = []
    for info in pkgutil.iter_modules(package.__path__):
        if info.name in ("main", "common") or info.name.startswith("_"):
            continue
        module = importlib.import_module(f"{__package__}.{info.name}")
        if hasattr(module, "register"):
            modules.append(module)
    return sorted(modules, key=lambda m: (getattr(m, "ORDER", 100), m.NAME))


#: an option value that starts with a minus sign and a digit ("-5uN", "-.5 nm") is a value, not an option
_NEGATIVE_VALUE = re.compile(r"^-\.?\d")


def _printable(text: str) -> str:
    """``text`` with control characters (terminal escape sequences, ...) escaped; newlines kept."""
    return "\n".join("".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in line)
                     for line in str(text).split("\n"))


class _Parser(argparse.ArgumentParser):
    """argparse with a short usage error: one line naming the problem and where the options are listed."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # argparse takes "-5uN" for an option; memstribo has no option that starts with a digit
        self._negative_number_matcher = _NEGATIVE_VALUE

    #: the command line being parsed (set by main), so that a usage error under --json is a JSON object too
    argv: list[str] = []

    def error(self, message):
        if "--json" in _Parser.argv:
            from memstribo.cli.common import error_object

            print(dumps_json(error_object(_printable(message), self.prog.partition(" ")[2] or None, "usage")))
        self.exit(EXIT_USAGE, f"{self.prog}: error: {_printable(message)}\nRun '{self.prog} --help' for the "
                              "options.\n")


def common_options() -> argparse.ArgumentParser:
    """Options every subcommand takes: --json, --set, --config, --parameter-set."""
    parent = _Parser(add_help=False)
    group = parent.add_argument_group("parameters and output")
    group.add_argument("--json", action="store_true", help="print exactly one JSON object of SI values")
    group.add_argument("--set", dest="overrides", action="append", default=[], metavar="NAME=VALUE",
                       help="override a model parameter; VALUE may carry a unit ('195.5 nm'); repeatable")
    group.add_argument("--config", metavar="FILE", help="TOML file of parameter overrides")
    group.add_argument("--parameter-set", default="silicon_thesis", metavar="NAME",
                       help="parameter set to start from (default: silicon_thesis), or a set file (.toml) such as 'memstribo "
                            "calibrate' writes")
    return parent


#: the namespace attribute where :class:`_GivenOnce` records each option's first value (removed by main)
_GIVEN = "_given_options"


class _GivenOnce:
    """Mixed into every single-valued option's action (issue #41): an option given twice with different values
    (``--refine --no-refine``, ``--config a.toml --config b.toml``) is refused rather than the last one silently
    winning, and an empty value (``--coating ''``, ``--out ''``, ``--values ''``) is refused rather than read as
    the option's absence. The same option given twice with the same value is harmless and accepted."""

    def __call__(self, parser, namespace, values, option_string=None):
        if isinstance(values, str) and not values.strip():
            raise argparse.ArgumentError(self, f"empty value {values!r}: give a value, or leave the option out "
                                               "for its default")
        if isinstance(self, argparse.BooleanOptionalAction):
            value, shown = not str(option_string).startswith("--no-"), str(option_string)
        elif isinstance(self, argparse._StoreConstAction):
            value, shown = self.const, str(option_string)
        else:
            value, shown = values, f"{option_string} {values}" if option_string else str(values)
        given = namespace.__dict__.setdefault(_GIVEN, {})
        if self.dest in given and given[self.dest][0] != value:
            raise argparse.ArgumentError(self, f"given twice with different values, '{given[self.dest][1]}' and "
                                               f"'{shown}': they contradict each other; give it once (memstribo "
                                               "does not let the last one win)")
        given.setdefault(self.dest, (value, shown))
        super().__call__(parser, namespace, values, option_string)


_ONCE_CLASSES: dict[type, type] = {}


def _given_once(parser: argparse.ArgumentParser) -> None:
    """Give every single-valued option of ``parser`` and its subcommands the :class:`_GivenOnce` checks."""
    single = (argparse._StoreAction, argparse._StoreConstAction, argparse.BooleanOptionalAction)
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                _given_once(sub)
        elif isinstance(action, single) and not isinstance(action, _GivenOnce):
            cls = type(action)
            if cls not in _ONCE_CLASSES:
                _ONCE_CLASSES[cls] = type(f"Once{cls.__name__}", (_GivenOnce, cls), {})
            action.__class__ = _ONCE_CLASSES[cls]


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="memstribo", description=DESCRIPTION, epilog=EPILOG,
                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"memstribo {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", title="commands")
    parents = [common_options()]
    for module in _command_modules():
        module.register(subparsers, parents)
    _given_once(parser)
    return parser


def load_parameters(args: argparse.Namespace):
    """The parameter set named by ``--parameter-set`` with ``--config`` then ``--set`` applied."""
    from memstribo.errors import InputError as MemstriboInputError
    from memstribo.parameters import get_parameter_values, parse_assignment, read_config

    params = get_parameter_values(args.parameter_set)
    args.config_tables = {}
    if args.config:
        config = read_config(args.config)
        params = params.updated(config.pop("parameters"), origin=f"config file {args.config}")
        args.config_tables = config
    if args.overrides:
        overrides = {}
        for text in args.overrides:
            name, value = parse_assignment(text)
            if name in overrides and overrides[name] != value:  # issue #41: not "the last one wins"
                raise MemstriboInputError(f"--set {name} is given twice with different values, '{overrides[name]}' "
                                          f"and '{value}': they contradict each other; give it once.")
            overrides[name] = value
        _imply_vdw_rule(params, overrides)
        params = params.updated(overrides, origin="--set")
    from memstribo.checks import check_unused_values

    check_unused_values(params)
    return params


def _imply_vdw_rule(params, overrides: dict) -> None:
    """``--set vdw_bond_energy=U`` alone states U_vdW itself: it selects the thesis's rule (U_vdW as given) where the
    set's rule is the default 'hysteresis' and nobody chose it, with a note on stderr (MODEL 7h). A rule the user
    chose is kept, and :func:`memstribo.checks.check_unused_values` refuses the contradiction."""
    from memstribo.checks import user_set

    if ("vdw_bond_energy" in overrides and "vdw_energy_rule" not in overrides
            and params.get("vdw_energy_rule") == "hysteresis" and not user_set(params, "vdw_energy_rule")):
        overrides["vdw_energy_rule"] = "thesis"
        print("note: --set vdw_bond_energy gives U_vdW itself, so the thesis's rule is used (vdw_energy_rule = thesis, "
              "MODEL 7h); the default rule derives it as phi w12 / n_site.", file=sys.stderr)


def _json_error(args, message: str, kind: str) -> None:
    """Under --json: the error as one JSON object on stdout (the message goes to stderr as well)."""
    if getattr(args, "json", False):
        from memstribo.cli.common import error_object

        try:
            print(dumps_json(error_object(message, args.command, kind)))
            sys.stdout.flush()
        except BrokenPipeError:  # pragma: no cover - the reader has gone
            pass


def _verbosity(args) -> None:
    """--verbose: the 'memstribo' logger's notes at INFO on stderr; --quiet: Python warnings silenced."""
    if args.command == "run":  # 'memstribo run' configures its own log lines
        return
    if getattr(args, "verbose", False):
        import logging

        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("memstribo: %(message)s"))
        logger = logging.getLogger("memstribo")
        logger.addHandler(handler)
        logger.setLevel(logging.INFO)
    elif getattr(args, "quiet", False):
        import warnings

        warnings.simplefilter("ignore")


def _complete(parser) -> None:
    """Shell completion with argcomplete when it is installed (``pip install "memstribo[completion]"``)."""
    if "_ARGCOMPLETE" not in os.environ:
        return
    try:
        import argcomplete
    except ImportError:  # pragma: no cover - optional
        return
    argcomplete.autocomplete(parser)


def main(argv: list[str] | None = None) -> int:
    # Not memstribo.heap.keep_freed_memory: it halves the CPU time of 2^16-point solves, but the damage stage's
    # peak memory grew from 12 to 16 GB with it (memstribo damage --json, 2026-11-23); opt-in for benchmarks.
    parser = build_parser()
    _Parser.argv = list(sys.argv[1:] if argv is None else argv)
    _complete(parser)
    args = parser.parse_args(argv)
    vars(args).pop(_GIVEN, None)
    from memstribo.output import set_command_line  # provenance: the command line in every file written

    set_command_line(["memstribo", *(sys.argv[1:] if argv is None else argv)])
    if not getattr(args, "handler", None):
        parser.print_help()
        return EXIT_USAGE
    _verbosity(args)
    try:
        params = load_parameters(args)
        result = args.handler(args, params)
    except MemstriboError as exc:
        _json_error(args, _printable(exc), "input")
        print(f"memstribo {args.command}: error: {_printable(exc)}", file=sys.stderr)
        return EXIT_USAGE
    except MemoryError:
        message = ("not enough memory for these inputs (steps, grid spacing, resample step or study size ask for "
                   "larger arrays than this machine holds); reduce them.")
        _json_error(args, message, "memory")
        print(f"memstribo {args.command}: error: {message}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print(f"memstribo {args.command}: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # a bug: say so briefly, full traceback on request
        if os.environ.get("MEMSTRIBO_DEBUG"):
            raise
        _json_error(args, f"internal error: {type(exc).__name__}: {_printable(exc)}", "internal")
        print(f"memstribo {args.command}: internal error: {type(exc).__name__}: {_printable(exc)}\n"
              "This is a bug in memstribo; rerun with MEMSTRIBO_DEBUG=1 for the traceback and report it.",
              file=sys.stderr)
        return 1
    if result is not None:
        if getattr(args, "quiet", False):
            result.notes = []  # --quiet: the values only (warnings stay in the values and in --json)
        try:
            print(dumps_json(result.json_values()) if args.json else result.to_text())
            sys.stdout.flush()
        except BrokenPipeError:  # e.g. `memstribo ... --json | head`: the reader has gone, not an error
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
        return result.exit_status
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
