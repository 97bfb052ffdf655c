// A curve or surface of the gmsh geometry kept as samples of its parametrization (points and
// derivatives), so that the solver can follow any curved boundary (ellipses, splines, CAD patches)
// on ranks and after meshing, where gmsh is gone. Cubic (curves) and bicubic (surfaces) Hermite
// interpolation between the samples; the closest point by a bounded search over the samples, then
// Newton in the parameters. Plain C++: free of gmsh and deal.II.
#pragma once

#include <array>
#include <vector>

namespace compliant
{
  struct ParametricSamples
  {
    std::vector<double> u;    // parameters of the samples along the curve, or the surface's first
    std::vector<double> v;    // the surface's second parameter; empty for a curve
    std::vector<double> data; // per sample (v fastest): curve x, x_u; surface x, x_u, x_v, x_uv

    bool         is_surface() const { return !v.empty(); }
    unsigned int n_values() const { return is_surface() ? 12 : 6; } // doubles per sample

    template <class Archive>
    void serialize(Archive &archive, const unsigned int)
    {
      archive &u &v &data;
    }
  };

  using Vector3 = std::array<double, 3>;

  // The interpolated point and its derivatives at parameters (u, v) (v ignored on a curve;
  // parameters outside the samples are clamped to them).
  struct SampledPoint
  {
    Vector3 x{}, x_u{}, x_v{}, x_uu{}, x_uv{}, x_vv{};
  };
  SampledPoint evaluate(const ParametricSamples &samples, double u, double v = 0);

  // The samples with a bounding ball per block of neighbouring samples, for closest-point search.
  class SampledShape
  {
  public:
    explicit SampledShape(ParametricSamples samples);

    // The point of the curve or surface closest to p (the parameters found, if asked for).
    Vector3 closest_point(const Vector3 &p, std::array<double, 2> *parameters = nullptr) const;

    // The weighted average of points on or near the shape, projected onto it: how a manifold
    // places new vertices and mapping points between existing ones.
    Vector3 project_average(const std::vector<Vector3> &points, const std::vector<double> &weights) const;

    const ParametricSamples &samples() const { return data; }

  private:
    struct Block
    {
      unsigned int i0, i1, j0, j1; // sample index ranges [i0, i1] x [j0, j1]
      Vector3      centre;
      double       radius;
    };
    ParametricSamples  data;
    std::vector<Block> blocks;

    Vector3 sample(unsigned int i, unsigned int j) const;
    void    newton(const Vector3 &p, double &u, double &v) const;
  };
} // namespace compliant
