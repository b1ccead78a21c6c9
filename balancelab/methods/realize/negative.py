"""Negative free length: an ordinary spring and a partner in parallel make a ZFL pair.

Source: Deepak & Ananthasuresh 2012, Sec. 1.1 (a negative-free-length spring in parallel
with an ordinary one behaves like a zero-free-length spring); Lecture 35, ``k = m g r / (b c)``.
"""
from __future__ import annotations

from ...core.design import Design
from ...core.elements import G, Load, Spring
from ...core.validation import MIN_POSITIVE, finite_real
from ...mechanisms.lever import lever_design
from ..registry import register

__all__ = ["negative_free_length_partner", "parallel_springs_lever"]

def negative_free_length_partner(k: float, free_length: float, k_partner: float) -> float:
    """Free length of a spring that, in parallel with ``(k, free_length)``, makes a ZFL pair.

    Two springs between the same points pull with ``k (d - l0) + k' (d - l0')``; the
    pair is a ZFL spring of stiffness ``k + k'`` when ``k l0 + k' l0' = 0``, i.e.
    ``l0' = -k l0 / k'`` (negative for an ordinary ``l0 > 0``; Deepak Sec. 1.1).

    Parameters
    ----------
    k : float
        Stiffness of the given spring (N/m), > 0.
    free_length : float
        Its free length (m).
    k_partner : float
        Stiffness of the partner (N/m), > 0.

    Returns
    -------
    float
        The partner's free length (m).

    Examples
    --------
    >>> negative_free_length_partner(100.0, 0.05, 50.0)
    -0.1
    """
    k = finite_real("k (N/m)", k, positive=True)
    free_length = finite_real("free_length (m)", free_length)
    k_partner = finite_real("k_partner (N/m)", k_partner, positive=True)
    return -k * free_length / k_partner


def parallel_springs_lever(mass: float = 2.0, length: float = 0.5, b: float = 0.3, c: float = 0.2,
                           free_length: float = 0.05, share: float = 0.5) -> Design:
    """The single link balanced by an ordinary spring and a negative-free-length partner in parallel.

    The lecture's ZFL stiffness ``k = m g r / (b c)`` is split: ``k1 = share k`` with
    free length ``free_length > 0`` and ``k2 = (1 - share) k`` with the free length of
    :func:`negative_free_length_partner`. Together they are exactly a ZFL spring, so
    the link is balanced.

    Parameters
    ----------
    mass, length, b, c : float
        As in :func:`balancelab.lecture.single_link_spring`: the mass (kg) at the tip of
        the link of length ``length`` (m), the anchor height ``b`` and the attachment
        distance ``c`` (m), all > 0.
    free_length : float
        Free length of the ordinary spring (m), > 0.
    share : float
        Part of ``k`` carried by the ordinary spring, in (0, 1).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = parallel_springs_lever()
    >>> d.balance_report().balanced, round(d.parameters["free_length_2"], 3)
    (True, -0.05)
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    b = finite_real("b (m)", b, positive=True)
    c = finite_real("c (m)", c, positive=True)
    free_length = finite_real("free_length (m)", free_length, positive=True)
    share = finite_real("share", share)
    if not 0 < share < 1:
        raise ValueError(f"share must be in (0, 1), got {share}")
    k = mass * G * r / (b * c)
    k1, k2 = share * k, (1 - share) * k
    if min(k1, k2) < MIN_POSITIVE:
        raise ValueError(f"share = {share} leaves a spring of stiffness {min(k1, k2):g} N/m: choose share "
                         "in (0, 1) away from its ends")
    l2 = negative_free_length_partner(k1, free_length, k2)
    springs = [Spring(k1, free_length, (0, (0.0, b)), (1, (c, 0.0)), name="k1"),
               Spring(k2, l2, (0, (0.0, b)), (1, (c, 0.0)), name="k2 (negative free length)")]
    return lever_design("lever with an ordinary and a negative-free-length spring in parallel",
                        [Load(1, (r, 0.0), (0.0, -mass * G), "m", kind="weight")], springs,
                        labels={"A": (0, (0.0, 0.0)), "B": (0, (0.0, b)), "C": (1, (c, 0.0))},
                        parameters={"k": k, "k1": k1, "k2": k2, "free_length_1": free_length,
                                    "free_length_2": l2},
                        reference="Deepak & Ananthasuresh 2012, Sec. 1.1; Lecture 35, k = m g r / (b c)")


register("negative_free_length_lever", "Negative free length: an ordinary spring in parallel with a "
         "partner (Deepak & Ananthasuresh, Sec. 1.1)", parallel_springs_lever, chapter=3)
