"""Making a ZFL spring real: string over a pulley, negative free length, ordinary springs,
and exact balance with an ordinary spring over a non-circular pulley.

Sources: Lecture 35 (*Theory of Mechanisms*), realizing a zero-free-length spring with
a string over a pulley and approximate balancing with regular (or gas) springs;
Deepak & Ananthasuresh 2012, Sec. 1.1 (a negative-free-length spring in parallel with an
ordinary one) and Sec. 2.3 / Fig. 20 (the pulley-and-string arrangement of the prototype).

One module per concept:

* :mod:`.pulley`: the exact model of a string over a round pulley (:func:`pulley_string`,
  :func:`pulley_lever`, :func:`pulley_energy`, :func:`pulley_balance_error`);
* :mod:`.negative`: an ordinary spring with a negative-free-length partner;
* :mod:`.optimizer`: the best ordinary spring placed by an optimizer (approximate balance);
* :mod:`.noncircular`: a cable from a real spring wound on a non-circular pulley whose
  profile makes the balance exact (:func:`noncircular_pulley`), :mod:`.noncircular_synthesis`
  (the profile from the energy it balances, and whether a cable can wrap it), :mod:`.profile`
  (the profile's geometry and the cable on it) and :mod:`.profile_export`,
  the profile as SVG, DXF and CSV files at true scale, checked as written (:mod:`.profile_check`);
* :mod:`.sleeve`: a normal spring mounted between a sleeve pivoted at the anchor and a rod
  sliding in it, which balances the lecture's link exactly (:func:`sleeve_lever`);
* :mod:`.normal_springs`: the same mount for every ZFL spring of any design
  (:func:`mount_normal_springs`, :func:`balance_normal`, :func:`normal_spring_derivation`).

Every name is importable from ``balancelab.methods.realize`` (``bl.realize``).
"""
# imported in course order: the registry orders a family's examples by module import
from .pulley import (PulleyError, PulleyString, pulley_balance_error, pulley_energy, pulley_error_curve,
                     pulley_lever, pulley_string)
from .negative import negative_free_length_partner, parallel_springs_lever
from .optimizer import ApproximationError, approximate_lever
from .profile import CableGeometry, NoncircularProfile, ProfileError
from .noncircular import noncircular_pulley, spring_limits
from .profile_export import ProfilePart, export_profile, profile_part
from .sleeve import sleeve_derivation, sleeve_lever
from .normal_springs import balance_normal, lamp_arm_normal_springs, mount_normal_springs, normal_spring_derivation

__all__ = [
    "PulleyString",
    "pulley_string",
    "pulley_lever",
    "pulley_energy",
    "PulleyError",
    "pulley_balance_error",
    "pulley_error_curve",
    "negative_free_length_partner",
    "parallel_springs_lever",
    "ApproximationError",
    "approximate_lever",
    "CableGeometry",
    "NoncircularProfile",
    "ProfileError",
    "noncircular_pulley",
    "spring_limits",
    "ProfilePart",
    "profile_part",
    "export_profile",
    "sleeve_lever",
    "sleeve_derivation",
    "mount_normal_springs",
    "balance_normal",
    "normal_spring_derivation",
    "lamp_arm_normal_springs",
]
