"""The ``memstribo`` command line: a thin layer over the library.

Each subcommand is one module in this package that defines ``NAME``, ``HELP``, ``ORDER``
(position in ``--help``), ``register(subparsers, parents)`` and ``run(args, params)``;
:mod:`memstribo.cli.main` discovers them. ``run`` returns a :class:`CommandResult`;
the framework prints it as a readable table with units, or with ``--json`` as exactly one
JSON object of SI values. Keep these modules light: import heavy libraries inside ``run``.
"""

from memstribo.cli.common import CommandResult, format_quantity

__all__ = ["CommandResult", "format_quantity"]
