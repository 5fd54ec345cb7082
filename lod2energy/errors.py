"""The project's exceptions: one root error and a few narrow subclasses.

Each error that concerns user input carries a val3dity-style code (901-904) so the
CLI and reports can show it without a traceback.
"""


class Lod2EnergyError(Exception):
    """Root of every error raised on purpose by lod2energy."""

    code = 999


class InputError(Lod2EnergyError, ValueError):
    """The input file (or one feature of it) cannot be used: val3dity 901."""

    code = 901


class EmptyPrimitiveError(InputError):
    """The input holds no primitive to validate: val3dity 902."""

    code = 902


class ParameterError(Lod2EnergyError, ValueError):
    """Wrong command-line or API parameters: val3dity 903."""

    code = 903


class FormatNotSupportedError(InputError):
    """A file format (or CityJSON version) the readers do not know: val3dity 904."""

    code = 904


class ExportError(Lod2EnergyError, RuntimeError):
    """An exported file failed its self-check."""

    code = 950
