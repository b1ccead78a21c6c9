"""`Linkage`: build a design of your own, body by body, joint by joint.

Bodies are named (strings; an integer is the index of an existing body, 0 the ground
``"ground"``) and created when first named. Joints are revolute (:meth:`Linkage.revolute`) or
prismatic (:meth:`Linkage.prismatic`, a slider whose slide ``s_<k>`` in metres becomes a
coordinate wherever the kinematics chooses it). Masses, constant forces and springs (any free length) sit at local
points of bodies: each body's local frame is the one its joint points are written in.
:meth:`Linkage.build` checks the topology and returns a :class:`balancelab.Design` on
:class:`.kinematics.LinkageKinematics`. Layer: mechanisms.
"""
from __future__ import annotations

import warnings

from typing import Mapping, Sequence

import numpy as np

from ...core.design import Design
from ...core.elements import Joint, Load, Spring, gravity_load
from ...core.validation import finite_real, planar_point
from .kinematics import LinkageKinematics
from .topology import Slider

__all__ = ["Linkage", "BodyRef"]

#: a body: its name, or its index (0 is the ground)
BodyRef = str | int


class Linkage:
    """A planar linkage under construction: named bodies, revolute joints, masses, loads, springs.

    Parameters
    ----------
    name : str
        Title of the designs it builds.

    Examples
    --------
    The four-bar of issue 11: crank 0.4 m, coupler 1 m, rocker 0.8 m, ground pivots 1 m apart.

    >>> lk = Linkage("four-bar")
    >>> lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    >>> lk.revolute("crank", (0.4, 0.0), "coupler", (0.0, 0.0))
    >>> lk.revolute("coupler", (1.0, 0.0), "rocker", (0.8, 0.0))
    >>> lk.revolute("rocker", (0.0, 0.0), "ground", (1.0, 0.0))
    >>> lk.mass("crank", 2.0, com=(0.2, 0.0))
    >>> lk.load("coupler", (0.0, -30.0), com=(0.5, 0.1))
    >>> d = lk.build(guess={"crank": 1.0, "rocker": 1.5})
    >>> d.bodies, d.q_names, d.dof
    (('ground', 'crank', 'coupler', 'rocker'), ('theta_1',), 1)
    """

    def __init__(self, name: str = "linkage") -> None:
        self.name = str(name)
        self._bodies: list[str] = ["ground"]
        self._joints: list[Joint] = []
        self._sliders: list[Slider] = []
        self._strokes: list = []
        self._loads: list[Load] = []
        self._springs: list[Spring] = []
        self._labels: dict = {}

    @property
    def bodies(self) -> tuple[str, ...]:
        """Names of the bodies so far, the ground first."""
        return tuple(self._bodies)

    def body(self, name: str) -> int:
        """Declare a new body ``name`` (fixes the body order) and return its index.

        Raises
        ------
        ValueError
            If a body of that name exists already (duplicate names).

        Examples
        --------
        >>> Linkage().body("arm")
        1
        """
        if not isinstance(name, str) or not name.strip():
            raise TypeError(f"a body name must be a non-empty str, got {name!r}")
        if name in self._bodies:
            raise ValueError(f"duplicate body name {name!r}: a body of that name exists already "
                             f"(bodies: {self._bodies})")
        self._bodies.append(name)
        return len(self._bodies) - 1

    def _index(self, body: BodyRef, what: str) -> int:
        if isinstance(body, bool):
            raise TypeError(f"{what} must be a body name (str) or index (int), got {body!r}")
        if isinstance(body, int):
            if not 0 <= body < len(self._bodies):
                raise ValueError(f"{what} index must be in 0..{len(self._bodies) - 1} (existing bodies "
                                 f"{self._bodies}), got {body}")
            return body
        if not isinstance(body, str) or not body.strip():
            raise TypeError(f"{what} must be a body name (str) or index (int), got {body!r}")
        return self._bodies.index(body) if body in self._bodies else self.body(body)

    def revolute(self, body_a: BodyRef, point_a, body_b: BodyRef, point_b) -> None:
        """Join ``point_a`` of ``body_a`` and ``point_b`` of ``body_b`` (local points, m) by a pin.

        Examples
        --------
        >>> lk = Linkage()
        >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
        >>> lk.bodies
        ('ground', 'arm')
        """
        a, b = self._index(body_a, "body_a"), self._index(body_b, "body_b")
        if a == b:
            raise ValueError(f"a joint must join two different bodies; both sides are {self._bodies[a]!r}")
        joint = Joint(a, planar_point("point_a (m)", point_a), b, planar_point("point_b (m)", point_b))
        flipped = Joint(joint.body_j, joint.point_j, joint.body_i, joint.point_i)
        if joint in self._joints or flipped in self._joints:
            raise ValueError(f"duplicate joint: {self._bodies[a]!r} {joint.point_i} and {self._bodies[b]!r} "
                             f"{joint.point_j} are joined already")
        self._joints.append(joint)

    def prismatic(self, body_a: BodyRef, point_a, body_b: BodyRef, point_b, axis=(1.0, 0.0),
                  stroke=None) -> str:
        """A slider: ``point_b`` of ``body_b`` moves along the line through ``point_a`` of ``body_a``
        with direction ``axis`` (in ``body_a``'s frame), and the two bodies keep their relative angle.

        Parameters
        ----------
        body_a, body_b : str or int
            The body that carries the line (the guide) and the body that slides on it.
        point_a, point_b : (float, float)
            Local points (m); the slide ``s`` is the distance of ``point_b`` from ``point_a`` along ``axis``.
        axis : (float, float)
            Direction of the line in ``body_a``'s frame (any length but zero; it is normalized).
        stroke : (float, float), optional
            Range of the slide (m) when it is a coordinate; default ``(-2 L, 2 L)`` with ``L`` the
            linkage's largest joint coordinate. A closed loop may limit it further.

        Returns
        -------
        str
            The slide's coordinate name ``s_<k>`` (k = 1, 2, ... in the order of the sliders), also
            accepted by ``build(driving=...)``.

        Examples
        --------
        A block on a horizontal guide, pulled back to the middle by a spring:

        >>> lk = Linkage("block")
        >>> lk.prismatic("ground", (0.0, 0.0), "block", (0.0, 0.0), axis=(1.0, 0.0), stroke=(-0.5, 0.5))
        's_1'
        >>> lk.spring("block", (0.0, 0.0), "ground", (0.0, 0.0), k=100.0)
        >>> d = lk.build()
        >>> d.q_names, d.q_range.tolist()
        (('s_1',), [[-0.5, 0.5]])
        """
        a, b = self._index(body_a, "body_a"), self._index(body_b, "body_b")
        if a == b:
            raise ValueError(f"a joint must join two different bodies; both sides are {self._bodies[a]!r}")
        ux, uy = planar_point("axis", axis)
        norm = float(np.hypot(ux, uy))
        if not norm > 1e-12:
            raise ValueError(f"axis must be a nonzero direction (u_x, u_y), got {axis!r}")
        if stroke is not None:
            lo, hi = planar_point("stroke (m)", stroke)
            if not lo < hi:
                raise ValueError(f"stroke must be (lo, hi) in metres with lo < hi, got {stroke!r}")
            stroke = (lo, hi)
        self._sliders.append(Slider(a, planar_point("point_a (m)", point_a), b, planar_point("point_b (m)", point_b),
                                    (ux / norm, uy / norm)))
        self._strokes.append(stroke)
        return f"s_{len(self._sliders)}"

    def mass(self, body: BodyRef, mass: float, com=(0.0, 0.0), name: str = "", *, at=None) -> None:
        """Hang a mass ``mass`` (kg) at the local point ``com`` (m) of ``body`` (its weight, g along -y).

        ``at=`` is the old name of ``com`` (deprecated: a ``DeprecationWarning``).

        Examples
        --------
        >>> lk = Linkage()
        >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
        >>> lk.mass("arm", 2.0, com=(0.5, 0.0))
        >>> lk.build().loads[0].force
        (0.0, -19.62)
        """
        com = _renamed("Linkage.mass", at, com)
        b = self._index(body, "body")
        self._loads.append(gravity_load(b, planar_point("com (m)", com), mass, name=name))

    def load(self, body: BodyRef, force, com=(0.0, 0.0), name: str = "", *, at=None) -> None:
        """Apply a constant ``force`` ``(f_x, f_y)`` (N, global frame) at the local point ``com`` of ``body``.

        ``at=`` is the old name of ``com`` (deprecated: a ``DeprecationWarning``).

        Examples
        --------
        >>> lk = Linkage()
        >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
        >>> lk.load("arm", (5.0, 0.0), com=(0.3, 0.0))
        >>> lk.build().loads[0].force
        (5.0, 0.0)
        """
        com = _renamed("Linkage.load", at, com)
        b = self._index(body, "body")
        self._loads.append(Load(b, planar_point("com (m)", com), planar_point("force (N)", force, unit="N"), name=name))

    def spring(self, body_a: BodyRef, point_a, body_b: BodyRef, point_b, k: float,
               free_length: float = 0.0, name: str = "") -> None:
        """A linear spring of rate ``k`` (N/m) and ``free_length`` (m; 0 is a ZFL spring) between two points.

        A negative ``free_length`` is allowed: it models a built spring that acts as a ZFL spring
        in parallel with a pretension (see :class:`balancelab.Spring` and the realizations).

        Examples
        --------
        >>> lk = Linkage()
        >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
        >>> lk.spring("arm", (0.2, 0.0), "ground", (0.0, 0.3), k=100.0)
        >>> lk.build().springs[0].is_zfl
        True
        """
        a, b = self._index(body_a, "body_a"), self._index(body_b, "body_b")
        self._springs.append(Spring(finite_real("k (N/m)", k, positive=True), free_length,
                                    (a, point_a), (b, point_b), name=name))

    def label(self, name: str, body: BodyRef, point) -> None:
        """Name a body point for the figures (``design.labels``).

        Examples
        --------
        >>> lk = Linkage()
        >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
        >>> lk.label("tip", "arm", (0.5, 0.0))
        >>> lk.build().labels["tip"]
        (1, (0.5, 0.0))
        """
        if name in self._labels:
            raise ValueError(f"duplicate label {name!r}")
        self._labels[str(name)] = (self._index(body, "body"), planar_point("point (m)", point))

    def _variable(self, ref, what: str) -> int:
        """A body's angle (its index) or a slide ``"s_<k>"`` (``nbodies + k - 1``)."""
        if isinstance(ref, str) and ref.startswith("s_") and ref[2:].isdigit() and ref not in self._bodies:
            k = int(ref[2:])
            if not 1 <= k <= len(self._sliders):
                raise ValueError(f"{what}: there is no slide {ref!r} (slides s_1..s_{len(self._sliders)})")
            return len(self._bodies) + k - 1
        if isinstance(ref, str) and ref not in self._bodies:
            raise ValueError(f"{what} must name a body {self._bodies} or a slide s_<k>, got {ref!r}")
        return self._index(ref, what)

    def _check(self) -> None:
        if len(self._bodies) < 2:
            raise ValueError("the linkage has no moving body: join one to the ground with revolute()")
        jointed = {b for j in self._joints for b in (j.body_i, j.body_j)}
        jointed |= {b for sl in self._sliders for b in (sl.body_a, sl.body_b)}
        lonely = [n for i, n in enumerate(self._bodies) if i and i not in jointed]
        if lonely:
            raise ValueError(f"bodies {lonely} have no joint: join each body to the linkage with revolute() "
                             "or prismatic()")

    def build(self, driving: Sequence[BodyRef] | None = None, guess: Mapping[BodyRef, float] | None = None,
              name: str | None = None) -> Design:
        """Check the linkage, assemble it and return its :class:`Design`.

        Parameters
        ----------
        driving : sequence of body names or indices, or slide names, optional
            Bodies whose absolute angles are the coordinates ``theta_<index>``, or slides
            ``"s_<k>"`` (as returned by :meth:`prismatic`), as many as the degrees of freedom;
            by default the earliest bodies (then slides) that determine the rest.
        guess : mapping of body to angle (rad), optional
            Body angles to start the assembly from: this picks the circuit (branch). Without it
            the assembly starts from the drawing (every body angle zero); a drawing at a change
            point (a parallelogram drawn flat) is moved onto the branch on which the most pairs
            of bodies keep their drawn relative angle (the parallelogram stays one).
        name : str, optional
            Title of the design (default: the linkage's name).

        Returns
        -------
        Design

        Raises
        ------
        ValueError
            For disconnected bodies, a body without a joint, an over-constrained linkage, a
            linkage that does not assemble, or driving bodies that do not determine the rest.
        """
        self._check()
        drive = None if driving is None else [self._variable(b, "driving") for b in driving]
        start = None if guess is None else {self._variable(b, "guess"): finite_real(f"guess[{b!r}] (rad or m)", a)
                                            for b, a in dict(guess).items()}
        pts = [v for j in self._joints for p in (j.point_i, j.point_j) for v in p]
        pts += [v for sl in self._sliders for p in (sl.point_a, sl.point_b) for v in p]
        if any(st is None for st in self._strokes) and not any(abs(v) > 0 for v in pts):
            raise ValueError(f"{self.name}: every joint point is at the origin, so a slider has no default stroke "
                             "(twice the largest coordinate either way): pass stroke=(lo, hi) (m) to prismatic()")
        kin = LinkageKinematics(len(self._bodies), self._joints, drive, start, self._bodies, self._sliders,
                                self._strokes)
        title = self.name if name is None else name
        try:
            design = Design(title, self._bodies, self._joints, kin, self._loads, self._springs, labels=self._labels,
                            reference="balancelab.Linkage (numeric kinematics)")
        except RuntimeError as err:
            raise ValueError(f"{title}: the linkage does not move from where it is assembled ({err}); a loop is "
                             "probably stretched straight (its links exactly span the ground): change the joint "
                             "points") from None
        self._check_moves(design, kin)
        return design

    def _check_moves(self, design: Design, kin) -> None:
        """ValueError when the assembled linkage cannot move (a coordinate's range is round-off) or
        has no reachable configurations to sample."""
        span = np.ptp(np.asarray(kin.q_range, dtype=float), axis=-1)
        units = kin.scale[list(kin.driving)]
        for name, width, unit in zip(kin.names, span, units):
            if not width > 1e-3 * unit:  # a locked loop closes to round-off over ~1e-5 rad
                raise ValueError(
                    f"{design.name}: the linkage cannot move: {name} can only move by {width:.3g} "
                    f"{'rad' if unit == 1.0 else 'm'}; its links {', '.join(self._bodies[1:])} are locked by their "
                    f"joints (e.g. link lengths that only close the loop when drawn flat, a loop stretched straight); "
                    "change the joint points")
        try:
            design.sample(20, seed=0)
        except RuntimeError as err:
            raise ValueError(f"{design.name}: the linkage does not move from where it is assembled ({err}); "
                             "a loop is probably stretched straight: change the joint points") from None


def _renamed(where: str, old, new):
    """``new``, or ``old`` (given as ``at=``) with a DeprecationWarning: ``at`` became ``com``."""
    if old is None:
        return new
    warnings.warn(f"{where}: at= is deprecated, use com= (the point where the load acts)", DeprecationWarning,
                  stacklevel=3)
    return old
