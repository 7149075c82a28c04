"""sweepcdt's exceptions: the converter's exit codes as Python exceptions.

Every failure of the library reaches Python as one of these (or MemoryError, KeyboardInterrupt, or
RuntimeError for an internal error); nothing terminates the interpreter. ``exit_code`` is the code
``sweepcdt mesh`` exits with for the same failure.
"""


class Error(Exception):
    """Base class of sweepcdt's exceptions."""

    exit_code = 1


class InvalidInputError(Error, ValueError):
    """Unreadable or invalid input (exit code 3): a malformed file, an open, non-manifold or
    self-intersecting surface, an invalid PLC, NaN coordinates or point ids out of range.

    The message names the file and the element. Attributes: ``kind`` (e.g. ``"Syntax"``,
    ``"NonFinite"``, ``"IndexOutOfRange"``, ``"surface"``, ``"plc"``), ``file``, ``where``
    (``"line 12"``, ``"triangle 4"`` or ``""``) and ``problems``: a list of ``(kind, elements,
    message)`` for surface and PLC problems (elements are triangle or point indices).
    """

    exit_code = 3


class NoCdtError(Error):
    """No constrained Delaunay triangulation (exit code 4): with ``steiner="none"``, or when Steiner
    points did not converge. ``witness`` holds the vertex ids (0-based, welded input ids) of the
    face or simplex that could not be finished."""

    exit_code = 4
    witness = ()


class VertexRemovalError(Error, ValueError):
    """``EditableCdt`` cannot delete this vertex (the mesh is left unchanged): it is not a vertex of
    the triangulation (never was, or already deleted), or a corner of a constraining facet (deleting
    it would change the facet's shape), or a case not implemented — a vertex on the boundary of a
    facet in D >= 4. ``vertex`` is its id. (A
    deletion that would leave a PLC without a CDT raises ``NoCdtError`` instead, also with
    ``vertex``.) The exit code is that of a usage error: the caller named the wrong vertex."""

    exit_code = 2
    vertex = None


class OutputError(Error, OSError):
    """An output file could not be written (exit code 5); nothing is left under its name."""

    exit_code = 5


class CheckError(Error):
    """``check=True`` found the computed triangulation invalid (exit code 6); ``failures`` lists
    ``(check, detail)`` pairs."""

    exit_code = 6
    failures = ()


class CancelledError(Error):
    """The progress callback returned False (exit code 130, as for Ctrl-C, which raises
    KeyboardInterrupt instead)."""

    exit_code = 130
