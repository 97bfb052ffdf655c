// Link lengths of a planar four-bar A-B-C-D with the numbering of the flap paper
// (seed 000, Table 1): ground AD = l1, crank AB = l2, coupler BC = l3, rocker CD = l4.
#pragma once

#include <array>

namespace compliant
{
  namespace four_bar
  {
    struct LinkLengths
    {
      double ground;  // l1 = |AD|, A at the origin, D on the positive x axis
      double crank;   // l2 = |AB|, the input link, pivoted at A
      double coupler; // l3 = |BC|
      double rocker;  // l4 = |CD|, the output link, pivoted at D

      std::array<double, 4> as_array() const { return {ground, crank, coupler, rocker}; }
      double                longest() const;
    };

    // Throws std::invalid_argument naming the link if a length is not positive and finite.
    void check_link_lengths(const LinkLengths &lengths);
  } // namespace four_bar
} // namespace compliant
