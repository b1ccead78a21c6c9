"""Lecture 35 of *Theory of Mechanisms*: balancing with counterweights and ZFL springs.

Single links (counterweight, ZFL spring, ordinary spring), the basic balancer
:func:`link_spring`, 2R arms with parallelograms, and the gravity four-bar through its
coupler's equivalent masses.
"""
# imported in course order: the registry orders a family's examples by module import
from .lever import (link_spring, single_link_counterweight, single_link_ordinary_spring,
                    single_link_spring)
from .serial import serial_2r_base_springs, serial_2r_parallelogram
from .fourbar import equivalent_masses, fourbar_counterweights, fourbar_two_springs

__all__ = ["equivalent_masses", "fourbar_counterweights", "fourbar_two_springs", "link_spring",
           "single_link_counterweight", "single_link_ordinary_spring", "single_link_spring",
           "serial_2r_base_springs", "serial_2r_parallelogram"]
