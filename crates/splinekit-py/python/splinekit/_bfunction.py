"""B-functions B: [0, 1] → [0, 1] with B(0) = 0, B(1) = 1, the blending weights of
blending splines (docs/format.md, "B-functions")."""

from ._splinekit import load


class BFunction:
    """A B-function as a callable ``B(t, nu=0)``: the value (nu = 0) or the nu-th
    derivative at t in [0, 1]; a number for a number, an array of shape (N,) for N
    parameters.

    Kinds and their parameters (as the ``bfunction`` documents):

    * ``"erbs"`` (``alpha``, ``beta``, ``gamma``, ``lambda``; defaults 1, 1, 1, ½):
      B(t) = ∫₀ᵗ φ / ∫₀¹ φ with φ(s) = exp(−β |s − λ|^{α(1+γ)} / (s (1 − s)^γ)^α), to full
      double precision, derivatives of every order exact;
    * ``"polynomial"`` (``smoothness`` k): k = 1 is 3t² − 2t³, k = 2 is 6t⁵ − 15t⁴ + 10t³, …;
    * ``"trigonometric"``: t − sin(2πt)/(2π); ``"linear"``: t; and the other kinds of
      docs/format.md.

    Bad parameters raise ``DocumentError`` (a ``ValueError``) with the command line's message.
    """

    def __init__(self, kind="erbs", **params):
        self.document = {"type": kind, **params}
        self._curve = load({"type": "bfunction", "bfunction": self.document})

    def __call__(self, t, nu=0):
        out = self._curve(t, nu)[..., 0]
        return float(out) if out.ndim == 0 else out

    def to_dict(self):
        """The B-function's document (``{"type": kind, **params}``), as the ``bfunction``
        field of blending-spline documents takes it."""
        return dict(self.document)

    def __repr__(self):
        return f"BFunction({self.document!r})"

    # Travels as its document (pickle, copy, deepcopy) and compares by it: the rebuilt
    # B-function is the same function, bit for bit.
    def __reduce__(self):
        return (_from_document, (dict(self.document),))

    def __eq__(self, other):
        if not isinstance(other, BFunction):
            return NotImplemented
        return self.document == other.document

    __hash__ = None  # type: ignore[assignment]  # equal by a mutable document: unhashable


def _from_document(document):
    """The ``BFunction`` of a document ``{"type": kind, **params}`` (what pickle calls)."""
    params = dict(document)
    return BFunction(params.pop("type"), **params)


def bfunction(kind="erbs", **params):
    """The B-function of ``kind`` with ``params`` as a callable ``B(t, nu=0)`` (see
    ``BFunction``). Python keywords that are reserved words (``lambda``) go through a
    dict: ``bfunction("erbs", **{"lambda": 0.3})``."""
    return BFunction(kind, **params)
