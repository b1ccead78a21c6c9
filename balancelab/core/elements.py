"""The parts a design is made of: loads, springs and revolute joints.

Conventions (see the notation page of the book):

* SI units throughout: metres, newtons, newtons per metre, kilograms, radians.
* Gravity is ``G = 9.81`` m/s^2 along ``-y``; a weight is the constant load ``(0, -m G)``.
* Body 0 is the ground. Every moving body has a local frame whose origin is its
  proximal joint and whose x-axis runs along the link; points on a body are given
  in that local frame.
* A spring with ``free_length == 0`` is a zero-free-length (ZFL) spring: its force is
  ``k`` times its *length*, not its extension.

Sign convention of a spring (as in :class:`sympy.physics.mechanics.LinearSpring`):
the spring pulls its two attachments together when it is longer than its free length,
and its potential energy is ``k/2 (|b - a| - free_length)^2`` whatever its direction.
A constant load ``f`` acting at a point ``r`` has potential energy ``-f . r``; for a
weight that is ``m G y``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, NamedTuple, Sequence, TypeAlias

from .validation import body_index, finite_real, planar_point

if TYPE_CHECKING:
    import numpy as np

__all__ = ["G", "Attachment", "CablePath", "Joint", "Load", "Pulley", "Spring", "SymbolicParts", "gravity_load"]

#: Gravitational acceleration (m/s^2), acting along -y.
G: float = 9.81


_REALIZATIONS = ("coil", "gas", "pulley")

#: a load of :class:`SymbolicParts`: ``(body, (x, y), (f_x, f_y))`` with sympy expressions
SymbolicLoad = tuple[int, tuple[Any, Any], tuple[Any, Any]]
#: a spring of :class:`SymbolicParts`: ``(k, free_length, (body, (x, y)), (body, (x, y)))``
SymbolicSpring = tuple[Any, Any, tuple[int, tuple[Any, Any]], tuple[int, tuple[Any, Any]]]


class _AttachmentFields(NamedTuple):
    body: int
    point: tuple[float, float]


class Attachment(_AttachmentFields):
    """A point fixed to a body: ``body`` index and ``point`` in its local frame (m).

    Examples
    --------
    >>> Attachment(1, (0.2, 0))
    Attachment(body=1, point=(0.2, 0.0))
    """

    __slots__ = ()

    def __new__(cls, body: int, point) -> Attachment:
        return super().__new__(cls, body_index("attachment body", body), planar_point("attachment point", point))


#: what a spring end may be given as: an Attachment or a pair ``(body, (x, y))``
AttachmentLike: TypeAlias = "Attachment | tuple[int, Sequence[float]]"


def _attachment(name: str, value: AttachmentLike) -> Attachment:
    if isinstance(value, Attachment):
        return value
    try:
        body, point = value
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair (body, (x, y)), got {value!r}") from None
    body_index(f"{name} body", body)
    planar_point(f"{name} point", point)
    return Attachment(body, point)


class Joint(NamedTuple):
    """A revolute joint: ``point_i`` on ``body_i`` coincides with ``point_j`` on ``body_j``."""

    body_i: int
    point_i: tuple[float, float]
    body_j: int
    point_j: tuple[float, float]


@dataclass(frozen=True)
class Load:
    """A constant force acting at a point of a body.

    Parameters
    ----------
    body : int
        Index of the body the load acts on (0 is the ground).
    point : (float, float)
        Point of action in the body's local frame (m).
    force : (float, float)
        The force in the global frame (N). A weight of mass ``m`` is ``(0, -m G)``.
    name : str, optional
        Label used in figures and reports.
    kind : {"weight", "counterweight", "force"}
        How the load is drawn: a weight or external force as an arrow, a
        counterweight as a disc.

    Examples
    --------
    >>> Load(1, (0.5, 0.0), (0.0, -9.81)).force
    (0.0, -9.81)
    """

    body: int
    point: tuple[float, float]
    force: tuple[float, float]
    name: str = ""
    kind: str = "force"

    if TYPE_CHECKING:  # the generated __init__ takes any pair of numbers (a list, an array) for point and force
        def __init__(self, body: int, point: Sequence[float], force: Sequence[float], name: str = "",
                     kind: str = "force") -> None: ...

    def __post_init__(self) -> None:
        object.__setattr__(self, "body", body_index("load body", self.body))
        object.__setattr__(self, "point", planar_point("load point", self.point))
        object.__setattr__(self, "force", planar_point("load force (N)", self.force, unit="N"))
        if self.kind not in ("weight", "counterweight", "force"):
            raise ValueError(f"load kind must be 'weight', 'counterweight' or 'force', got {self.kind!r}")

    @property
    def mass(self) -> float:
        """Mass (kg) equivalent to a downward force of this size: ``-force_y / G``."""
        return -self.force[1] / G


def gravity_load(body: int, point: Sequence[float], mass: float, name: str = "", kind: str = "weight") -> Load:
    """Return the weight of a mass ``mass`` (kg) at ``point`` of ``body`` as a :class:`Load`.

    Parameters
    ----------
    body : int
        Body carrying the mass.
    point : (float, float)
        Centre of mass in the body's local frame (m).
    mass : float
        Mass in kg; must be > 0.
    name : str, optional
        Label for figures.
    kind : {"weight", "counterweight"}
        Drawn as an arrow or as a disc.

    Returns
    -------
    Load
        The load ``(0, -mass G)`` at ``point``.

    Examples
    --------
    >>> gravity_load(1, (0.3, 0.0), 2.0).force
    (0.0, -19.62)
    """
    mass = finite_real("mass (kg)", mass)   # a computed mass may be tiny, not zero or negative
    if mass <= 0:
        raise ValueError(f"mass must be > 0 (kg), got {mass}")
    return Load(body, point, (0.0, -mass * G), name=name, kind=kind)


@dataclass(frozen=True)
class Pulley:
    """A spring realized as an ordinary spring pulling a string over a pulley.

    The pulley's centre is the spring's ground attachment ``a`` (the virtual anchor of
    the ideal ZFL spring). The real spring lies on the side ``spring_direction`` of the
    pulley; the string tied to it comes in parallel to ``-spring_direction``, wraps round
    the pulley counter-clockwise (``turn = 1``) or clockwise (``turn = -1``) and leaves
    on the tangent towards the attachment ``b`` on the moving link. The exact string
    model (:func:`balancelab.mechanisms.geometry.pulley_string`) and the drawing
    (:func:`balancelab.viz.draw`) both read this object.

    Parameters
    ----------
    radius : float
        Pulley radius (m), >= 0; 0 is the ideal point anchor (an exact ZFL spring).
    spring_direction : (float, float)
        Direction (global frame, any non-zero length) from the pulley towards the real
        spring; ``(0, 1)``: the spring hangs above the pulley.
    turn : {1, -1}
        Sense in which the string wraps round the pulley (1: counter-clockwise).

    Examples
    --------
    >>> p = Pulley(0.01)
    >>> p.radius, p.spring_direction, p.turn
    (0.01, (0.0, 1.0), 1)
    >>> Spring(100.0, 0.0, (0, (0.0, 0.3)), (1, (0.2, 0.0)), realization=p).pulley is p
    True
    """

    radius: float = 0.0
    spring_direction: tuple[float, float] = (0.0, 1.0)
    turn: int = 1

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", finite_real("pulley radius (m)", self.radius, nonnegative=True))
        direction = planar_point("pulley spring_direction", self.spring_direction)
        if direction == (0.0, 0.0):
            raise ValueError("pulley spring_direction must be a non-zero vector (x, y), got (0.0, 0.0)")
        object.__setattr__(self, "spring_direction", direction)
        if isinstance(self.turn, bool) or self.turn not in (1, -1):
            raise ValueError(f"pulley turn must be 1 (counter-clockwise) or -1 (clockwise), got {self.turn!r}")
        object.__setattr__(self, "turn", int(self.turn))

    def __str__(self) -> str:
        return f"string over a pulley of radius {self.radius:.4g} m"


class CablePath:
    """Base of a spring realization whose length runs along a cable path (a non-circular pulley).

    The spring's attachment ``a`` is its end on the ground side and ``b`` the cable's end on
    the moving body; between them the cable follows a path that only the realization knows
    (for instance the tangent from the anchor plus the arc wrapped on a profile fixed to the
    body). A subclass implements :meth:`length`; the design's energy is then
    ``k/2 (length - free_length)^2`` with that length, not the straight distance from ``a`` to
    ``b``. The concrete profile lives in :mod:`balancelab.methods.realize.noncircular`.
    Instances compare and hash by identity.
    """

    def length(self, pose_a: np.ndarray, pose_b: np.ndarray) -> np.ndarray:
        """Length (m) between the spring's load points, from the poses ``(x, y, angle)`` of its bodies.

        Parameters
        ----------
        pose_a, pose_b : numpy.ndarray, shape (..., 3)
            Poses of the bodies of attachments ``a`` and ``b``.

        Returns
        -------
        numpy.ndarray, shape (...)
        """
        raise NotImplementedError("a CablePath subclass must implement length(pose_a, pose_b)")


@dataclass(frozen=True)
class Spring:
    """A linear spring between two attachment points.

    The energy is ``k/2 (|b - a| - free_length)^2`` where ``a`` and ``b`` are the
    global positions of the two attachments. With ``free_length == 0`` the spring is a
    zero-free-length (ZFL) spring and its energy is ``k/2 |b - a|^2``: a quadratic
    function of the attachment coordinates, which is what makes exact balancing
    possible. A negative free length is allowed (a ZFL spring in parallel with an
    ordinary one behaves like one, Deepak & Ananthasuresh 2012, Sec. 1.1).

    Parameters
    ----------
    k : float
        Stiffness (N/m), > 0.
    free_length : float
        Free length (m); 0 for a ZFL spring.
    a, b : (int, (float, float))
        The two attachments as ``(body, local point)``.
    name : str, optional
        Label (for instance ``"k1"``).
    realization : {"coil", "gas", "pulley"} or Pulley or CablePath
        How the spring is built: a coil spring, a gas spring, or an ordinary spring
        pulling a string over a :class:`Pulley` centred at ``a`` (which must then be on
        the ground). ``"pulley"`` is short for ``Pulley()`` (an ideal pulley of radius
        0 with the spring above it). The design's energy is that of the ideal spring,
        except for a :class:`CablePath` (a cable over a non-circular pulley), whose
        length runs along the cable; the realization is what
        :mod:`balancelab.methods.realize` models exactly and what the figures draw.

    Examples
    --------
    >>> s = Spring(100.0, 0.0, (0, (0.0, 0.2)), (1, (0.1, 0.0)))
    >>> s.is_zfl, s.pulley
    (True, None)
    """

    k: float
    free_length: float
    a: Attachment
    b: Attachment
    name: str = ""
    realization: str | Pulley | CablePath = "coil"

    if TYPE_CHECKING:  # the generated __init__ also takes plain (body, (x, y)) pairs for a and b
        def __init__(self, k: float, free_length: float, a: AttachmentLike, b: AttachmentLike,
                     name: str = "", realization: str | Pulley | CablePath = "coil") -> None: ...

    def __post_init__(self) -> None:
        object.__setattr__(self, "k", finite_real("spring stiffness k (N/m)", self.k, positive=True))
        object.__setattr__(self, "free_length", finite_real("spring free_length (m)", self.free_length))
        object.__setattr__(self, "a", _attachment("spring attachment a", self.a))
        object.__setattr__(self, "b", _attachment("spring attachment b", self.b))
        if not isinstance(self.realization, (Pulley, CablePath)) and self.realization not in _REALIZATIONS:
            raise ValueError(f"spring realization must be one of {_REALIZATIONS}, a Pulley or a CablePath, "
                             f"got {self.realization!r}")
        if self.a.body == self.b.body:
            raise ValueError("a spring must join two different bodies; both attachments are on body "
                             f"{self.a.body}")
        if self.pulley is not None and self.a.body != 0:
            raise ValueError("a spring realized by a pulley has the pulley's centre at its attachment a, "
                             f"which must be on the ground (body 0), got body {self.a.body}")

    @property
    def is_zfl(self) -> bool:
        """True for a zero-free-length spring."""
        return self.free_length == 0.0

    @property
    def pulley(self) -> Pulley | None:
        """The :class:`Pulley` of a spring realized by a string over a pulley, else None."""
        if isinstance(self.realization, Pulley):
            return self.realization
        return Pulley() if self.realization == "pulley" else None

    @property
    def cable(self) -> CablePath | None:
        """The :class:`CablePath` of a spring whose length runs along a cable, else None."""
        return self.realization if isinstance(self.realization, CablePath) else None


@dataclass(frozen=True)
class SymbolicParts:
    """Loads and springs whose values are sympy expressions in named design parameters.

    A method that keeps its parameters symbolic builds its loads and springs twice from
    one builder: once with numbers (the design) and once with sympy symbols (this).
    ``values`` maps every free symbol to its number in the design. ``kinematics``, when
    given, is a kinematics whose joint points are sympy expressions too (link lengths as
    symbols); it is used only for :meth:`balancelab.Design.potential_energy_symbolic`.
    """

    loads: tuple[SymbolicLoad, ...] = ()
    springs: tuple[SymbolicSpring, ...] = ()
    values: dict[Any, float] = field(default_factory=dict)
    kinematics: Any = None  # a Kinematics whose points are sympy expressions, or None
