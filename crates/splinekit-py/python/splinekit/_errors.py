"""The exceptions splinekit raises, all under ``SplinekitError``.

Each also subclasses the built-in exception raised for it before these classes existed,
so ``except ValueError`` (or ``OSError``, ``RuntimeError``) still catches it. Messages are
the line the command line prints after ``error: `` (the field, then what is wrong with the
numbers).
"""

__all__ = ["SplinekitError", "DocumentError", "NumericalError", "BudgetError", "FileError", "RenderError"]


class SplinekitError(Exception):
    """The base of every error splinekit raises."""


class DocumentError(SplinekitError, ValueError):
    """A bad document or argument: a missing, malformed or out-of-range field, a count
    that does not match, a value that is not finite, a malformed STEP file."""


class NumericalError(SplinekitError, ValueError):
    """A computation that did not converge or has no finite value (a fit that is not
    determined, an offset that needs more than its limit of pieces, a mesh whose numbers a
    file format cannot hold)."""


class BudgetError(SplinekitError, ValueError):
    """A request over the memory or work budget (``SPLINEKIT_MAX_MEMORY``,
    ``SPLINEKIT_MAX_WORK``), refused before any work starts."""


class FileError(SplinekitError, OSError, ValueError):
    """A file that cannot be read or written."""


class RenderError(SplinekitError, RuntimeError):
    """No picture can be made: the package was built without the renderer, or there is
    no graphics adapter."""


for _cls in (SplinekitError, DocumentError, NumericalError, BudgetError, FileError, RenderError):
    _cls.__module__ = "splinekit"
del _cls
