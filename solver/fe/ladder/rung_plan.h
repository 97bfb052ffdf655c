// The ladder's refinement decision (plain C++): the element degree and the number of halvings of
// the case's mesh on rung k, the mesh size its estimate uses, and the word for the next step.
// Degree rungs: 2, 3, 4 on hexahedra (degree 1 locks in bending and is far from the asymptotic
// rate), then halved cells at the highest degree; FE_SimplexP stops at 2 (known once the first
// rung has built the mesh). Refinement = auto climbs in degree on 3D hexahedra (one degree step
// costs about 3x the DoFs where halving the cells costs 8x, and a uniform climb pays for the rung
// after the first that meets the target to observe an order: 5.5x the cheapest uniform mesh's
// whole process on the torsion bar, against 1.26x in degree); tetrahedra go uniform at degree 2
// after the first rung.
#pragma once

#include <string>

namespace compliant
{
  struct RungPlan
  {
    unsigned int degree;  // element degree of the rung
    unsigned int h_steps; // halvings of the case's mesh
    bool         refines_cells; // the rung halves the cells of the one before (not only a degree step)
  };

  class RungPlanner
  {
  public:
    static constexpr unsigned int lowest_degree = 2;

    RungPlanner(bool degree_rungs, unsigned int uniform_degree, unsigned int highest_degree = 4)
      : degree_rungs_(degree_rungs), uniform_degree_(uniform_degree), highest_degree_(highest_degree)
    {}

    // Rung k, counted from 0.
    RungPlan plan(unsigned int k) const;
    // The first rung's mesh has triangles or tetrahedra: degree 2 at most; under Refinement = auto
    // only halving is left, at degree 2.
    void simplex_mesh(bool automatic);

    bool         degree_rungs() const { return degree_rungs_; }
    unsigned int uniform_degree() const { return uniform_degree_; }
    unsigned int highest_degree() const { return highest_degree_; }

    // The mesh size h of rung k for the Richardson estimate: uniform rungs halve h exactly,
    // adaptive and degree rungs measure it by the DoF count, h = N^(-1/dim).
    double mesh_size(bool adaptive, unsigned int k, double dofs, int dim) const;
    // How rung k + 1 differs from rung k: "refine adaptively:", "raise the degree:" or "refine:".
    std::string next_step(bool adaptive, unsigned int k) const;

  private:
    bool         degree_rungs_;
    unsigned int uniform_degree_;
    unsigned int highest_degree_;
  };
} // namespace compliant
