"""The Peaucellier-Lipkin writing board balanced by ZFL springs (Singh Sec. III.B).

Bodies (Singh's numbering): 0 ground; 1 crank from pivot ``A`` to ``C``; 2 and 3 the long
arms from pivot ``O`` to ``D`` and ``E``; 4 and 5 rhombus sides ``C-D`` and ``C-E``; 6 and 7
rhombus sides ``D-P`` and ``E-P``. With ``|OA| = |AC| = d`` the point ``P`` (the board) moves
on the vertical line ``x = (l^2 - s^2) / (2 d)``: the inversion ``OC . OP = l^2 - s^2``.

Balancing (the paper's construction): the weights of bodies 4 and 5 are split between
their end joints; the crank then is a lever carrying ``W1`` at its midpoint and
``(W4 + W5)/2`` at ``C``, balanced by one ZFL spring with minimum preload (eqs 18-20).
Bodies 2-6 (side ``D``) and 3-7 (side ``E``) are two 2R arms (the board's load ``Wb``
split between them), each balanced by two ZFL springs on its second body only: with
``a_x2 = -a_x3`` and the minimum-preload anchors of eqs 29-31, eq. 51 with zero left side
gives ``k2 = k3 = (W_1' p_x1' + W_2' l) / (2 l^2)`` and
``a_x2 = l sqrt(W_2' p_x2' / (W_1' p_x1' + W_2' l))`` (primes: the 2R's own loads; see
:func:`arm_2r_springs`). Each side gets its own springs from its own weights (``W2, W4, W6``
for ``D``; ``W3, W5, W7`` for ``E``); with the paper's equal pairs they coincide. Each part
is balanced for every value of its own angles, so the whole linkage is balanced.

Assumed geometry: the paper's Figs 8-10 are not in its text. With the printed loads, the
values here reproduce every printed spring number (``k1 = 45.88``, ``k2 = k3 = 33.02`` N/m,
``a_x2 = -a_x3 = 0.468``, ``b_y2 = 1.218``, ``b_y3 = 0.283`` m, ``a_x1 = b_y1 = 0.2`` m): crank
``d = 0.22326`` m with its centre of mass at its midpoint; long arms ``l = 0.7505`` m
(``(b_y2 + b_y3)/2``) with their centres of mass ``0.232`` m from ``O``; rhombus sides
``s = 0.363`` m with centres of mass at their midpoints; the board's ``Wb = 72.03`` N acts
at ``P``.
"""
from __future__ import annotations

import math


from ..registry import example
from ...core.design import Design
from ...core.elements import Joint, Load, Spring
from ...core.validation import finite_real, finite_reals, planar_point
from ...mechanisms.peaucellier import PEAUCELLIER_BODIES, PeaucellierKinematics

__all__ = ["arm_2r_springs", "peaucellier_board"]


def arm_2r_springs(arm_weight: float, rhombus_weight: float, side_weight: float, board_weight: float,
                   arm_com: float, arm: float, side: float) -> tuple[float, float, float, float]:
    """Springs of one side of the board: the 2R arm ``O-D-P`` (or ``O-E-P``) (eqs 29-34, 51).

    The first body is the long arm (its weight at ``arm_com`` from ``O``, half of its
    rhombus side 4 or 5 at its tip), the second the side 6 or 7 (its weight at its
    midpoint, half of the board at ``P``). Two equal ZFL springs from anchors on the
    vertical through ``O`` to the points ``+-a_x`` of the second body, with the
    minimum-preload anchors ``b_y = l +- a_x``, balance it for all its angles.

    Parameters
    ----------
    arm_weight, rhombus_weight, side_weight : float
        Weights (N) of the long arm, of the rhombus side hinged at its tip, of the outer side.
    board_weight : float
        The board's whole load ``Wb`` (N); half of it acts on this side.
    arm_com, arm, side : float
        Centre of mass of the arm from ``O``, arm length ``l``, side length ``s`` (m).

    Returns
    -------
    (float, float, float, float)
        ``(k, a_x, b_y2, b_y3)``: the rate of both springs (N/m), the attachment (m) and
        the two anchor heights (m).

    Examples
    --------
    >>> k, ax, by2, by3 = arm_2r_springs(11.43, 4.78, 7.62, 72.03, 0.232, 0.7505, 0.363)
    >>> round(k, 2), round(ax, 3), round(by2, 3), round(by3, 3)
    (33.02, 0.468, 1.218, 0.283)
    """
    first = arm_weight * arm_com + (rhombus_weight / 2 + side_weight + board_weight / 2) * arm
    second = (side_weight / 2 + board_weight / 2) * side
    k = first / (2 * arm * arm)
    a_x = arm * math.sqrt(second / first)
    return k, a_x, arm + a_x, arm - a_x


@example("peaucellier_board", "Peaucellier-Lipkin writing board (Singh Sec. III.B: k1 = 45.88, "
         "k2 = k3 = 33.02 N/m)", chapter=6)
def peaucellier_board(weights=(6.88, 11.43, 11.43, 4.78, 4.78, 7.62, 7.62), board_weight: float = 72.03,
                      crank: float = 0.22326, arm: float = 0.7505, side: float = 0.363,
                      arm_com=(0.232, 0.0), a_x: float = 0.2) -> Design:
    """The Peaucellier-Lipkin writing board of Singh & Ananthasuresh, balanced (Sec. III.B).

    Parameters
    ----------
    weights : seven floats
        Weights of bodies 1-7 (N), > 0 (the paper's ``W1 ... W7``).
    board_weight : float
        The board's load ``Wb`` at ``P`` (N), >= 0.
    crank, arm, side : float
        Crank ``d``, long arm ``l`` and rhombus side ``s`` (m); see
        :class:`balancelab.PeaucellierKinematics`.
    arm_com : (float, float)
        Centre of mass ``(p_arm, 0)`` of arms 2 and 3 in their frames (m), on their axes.
    a_x : float
        Attachment ``a_x1`` of the crank's spring (m), > 0; its anchor is ``a_x1`` above ``A``.

    Returns
    -------
    Design
        Its ``parameters`` hold the springs of both sides: ``k2D, k3D, a_x2D, a_x3D, b_y2D,
        b_y3D`` and the same with ``E``; ``k2, k3, a_x2, a_x3, b_y2, b_y3`` are side ``D``'s
        (the paper's, which has equal sides). ``travel`` is the length (m) of the line that
        ``P`` reaches (see :attr:`PeaucellierKinematics.travel`).

    Examples
    --------
    >>> d = peaucellier_board()
    >>> round(d.parameters["k1"], 2), round(d.parameters["k2"], 2), round(d.parameters["a_x2"], 3)
    (45.88, 33.02, 0.468)
    """
    W = finite_reals("weights (the seven body weights W1..W7, N)", weights, 7, positive=True)
    Wb = finite_real("board_weight (N)", board_weight, nonnegative=True)
    p_arm, p_arm_y = planar_point("arm_com (m)", arm_com)
    if p_arm <= 0 or p_arm_y != 0:
        raise ValueError(f"arm_com must be (p_arm, 0) with p_arm > 0 (on the arms' axes), got {arm_com}")
    a_x1 = finite_real("a_x (m)", a_x, positive=True)
    kin = PeaucellierKinematics(crank, arm, side)
    d, l, s = kin.d, kin.l, kin.s
    # lever: crank with W1 at its midpoint and half of W4 and W5 at C (eqs 18-20)
    moment1 = W[0] * d / 2 + (W[3] + W[4]) / 2 * d
    k1 = moment1 / a_x1 ** 2
    # each side its own 2R: arm (own weight at p_arm, half of its rhombus side 4 or 5 at D or E),
    # then side 6 or 7 (own weight at s/2, Wb/2 at P)
    sides = {"D": arm_2r_springs(W[1], W[3], W[5], Wb, p_arm, l, s),
             "E": arm_2r_springs(W[2], W[4], W[6], Wb, p_arm, l, s)}
    A = (d, 0.0)
    loads = [Load(1, (d / 2, 0.0), (0.0, -W[0]), "W1", kind="weight")]
    loads += [Load(b, (p_arm if b < 4 else s / 2, 0.0), (0.0, -W[b - 1]), f"W{b}", kind="weight")
              for b in range(2, 8)]
    if Wb > 0:  # the board hangs at P, the joint of sides 6 and 7: half on each side
        loads += [Load(6, (s, 0.0), (0.0, -Wb / 2), "Wb/2", kind="force"),
                  Load(7, (s, 0.0), (0.0, -Wb / 2), "Wb/2", kind="force")]
    springs = [Spring(k1, 0.0, (0, (A[0], a_x1)), (1, (a_x1, 0.0)), name="k1")]
    per_side = {}
    for body, tag in ((6, "D"), (7, "E")):
        k, ax, by2, by3 = sides[tag]
        springs.append(Spring(k, 0.0, (0, (0.0, by2)), (body, (ax, 0.0)), name=f"k2{tag}"))
        springs.append(Spring(k, 0.0, (0, (0.0, by3)), (body, (-ax, 0.0)), name=f"k3{tag}"))
        per_side.update({f"k2{tag}": k, f"k3{tag}": k, f"a_x2{tag}": ax, f"a_x3{tag}": -ax,
                         f"b_y2{tag}": by2, f"b_y3{tag}": by3})
    k2, ax2, by2, by3 = sides["D"]
    joints = [Joint(0, A, 1, (0.0, 0.0)), Joint(0, (0.0, 0.0), 2, (0.0, 0.0)),
              Joint(0, (0.0, 0.0), 3, (0.0, 0.0)), Joint(1, (d, 0.0), 4, (0.0, 0.0)),
              Joint(1, (d, 0.0), 5, (0.0, 0.0)), Joint(2, (l, 0.0), 4, (s, 0.0)),
              Joint(3, (l, 0.0), 5, (s, 0.0)), Joint(2, (l, 0.0), 6, (0.0, 0.0)),
              Joint(3, (l, 0.0), 7, (0.0, 0.0)), Joint(6, (s, 0.0), 7, (s, 0.0))]
    return Design("Peaucellier-Lipkin writing board", PEAUCELLIER_BODIES, joints, kin, loads, springs,
                  labels={"O": (0, (0.0, 0.0)), "A": (0, A), "C": (1, (d, 0.0)), "D": (2, (l, 0.0)),
                          "E": (3, (l, 0.0)), "P": (6, (s, 0.0))},
                  parameters={"k1": k1, "a_x1": a_x1, "b_x1": 0.0, "b_y1": a_x1, "k2": k2, "k3": k2,
                              "a_x2": ax2, "a_x3": -ax2, "b_y2": by2, "b_y3": by3,
                              **per_side, "line_x": kin.line_x, "travel": kin.travel},
                  reference="Singh & Ananthasuresh, Sec. III.B (eqs 18-20, 29-34, 51)")
