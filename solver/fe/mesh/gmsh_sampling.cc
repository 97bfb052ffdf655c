#include "mesh/gmsh_sampling.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace compliant
{
  namespace
  {
    // Sampling doubles until Hermite interpolation between samples misses the parametrization
    // midway by at most `target` of the entity's size; capped, up to `acceptable` is still
    // followed (a kink of a low-degree spline converges slowly; 1e-7 of the size is far below
    // any mesh's resolution), beyond it the entity stays straight.
    constexpr double       target      = 1e-10;
    constexpr double       acceptable  = 1e-7;
    constexpr unsigned int max_curve   = 16384; // intervals along a curve
    constexpr unsigned int max_surface = 512;   // intervals along each parameter of a surface
    constexpr unsigned int max_grid    = 1 << 17; // samples of a surface

    std::vector<double> spaced(const double from, const double to, const unsigned int n)
    {
      std::vector<double> u(n + 1);
      for (unsigned int i = 0; i <= n; ++i)
        u[i] = from + (to - from) * i / n;
      u.back() = to;
      return u;
    }

    bool all_finite(const std::vector<double> &values, const std::size_t expected)
    {
      return values.size() == expected &&
             std::all_of(values.begin(), values.end(), [](const double x) { return std::isfinite(x); });
    }

    // The diagonal of the bounding box of the samples' points.
    double extent(const std::vector<double> &xyz)
    {
      double low[3] = {1e300, 1e300, 1e300}, high[3] = {-1e300, -1e300, -1e300}, squared = 0;
      for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
        for (unsigned int d = 0; d < 3; ++d)
          low[d] = std::min(low[d], xyz[i + d]), high[d] = std::max(high[d], xyz[i + d]);
      for (unsigned int d = 0; d < 3; ++d)
        squared += (high[d] - low[d]) * (high[d] - low[d]);
      return std::sqrt(squared);
    }

    // The largest distance between interpolated and true points at parameters uv (pairs for a
    // surface).
    double interpolation_error(const int dim, const int tag, const ParametricSamples &samples,
                               const std::vector<double> &uv)
    {
      std::vector<double> exact;
      gmsh::model::getValue(dim, tag, uv, exact);
      double largest = 0;
      for (std::size_t k = 0; 3 * k + 2 < exact.size(); ++k)
        {
          const auto p = dim == 1 ? evaluate(samples, uv[k]) : evaluate(samples, uv[2 * k], uv[2 * k + 1]);
          double     squared = 0;
          for (unsigned int d = 0; d < 3; ++d)
            squared += (p.x[d] - exact[3 * k + d]) * (p.x[d] - exact[3 * k + d]);
          largest = std::max(largest, std::sqrt(squared));
        }
      return largest;
    }

    std::string missed(const double error, const double size, const std::size_t n_samples)
    {
      char text[160];
      std::snprintf(text, sizeof text, "Hermite interpolation of %zu samples of its parametrization misses it by "
                    "%.1e of its size", n_samples, error / size);
      return text;
    }

    bool finite_bounds(const int dim, const int tag, std::vector<double> &min, std::vector<double> &max)
    {
      gmsh::model::getParametrizationBounds(dim, tag, min, max);
      if (min.size() != std::size_t(dim) || max.size() != std::size_t(dim))
        return false;
      for (int d = 0; d < dim; ++d)
        if (!std::isfinite(min[d]) || !std::isfinite(max[d]) || !(max[d] > min[d]))
          return false;
      return true;
    }

    std::string sample_curve(const int tag, ParametricSamples &samples)
    {
      std::vector<double> min, max;
      if (!finite_bounds(1, tag, min, max))
        return "its parametrization has no finite range";
      double error = 0, size = 0;
      for (unsigned int n = 32; n <= max_curve; n *= 2)
        {
          samples.u = spaced(min[0], max[0], n);
          samples.v.clear();
          std::vector<double> xyz, derivatives;
          gmsh::model::getValue(1, tag, samples.u, xyz);
          gmsh::model::getDerivative(1, tag, samples.u, derivatives);
          if (!all_finite(xyz, 3 * (n + 1)) || !all_finite(derivatives, 3 * (n + 1)))
            return "gmsh gives no finite values or derivatives of its parametrization";
          samples.data.resize(6 * (n + 1));
          for (unsigned int i = 0; i <= n; ++i)
            for (unsigned int d = 0; d < 3; ++d)
              samples.data[6 * i + d] = xyz[3 * i + d], samples.data[6 * i + 3 + d] = derivatives[3 * i + d];
          size = extent(xyz);
          if (!(size > 0))
            return "its parametrization is degenerate (one point)";
          std::vector<double> midpoints;
          for (unsigned int i = 0; i < n; ++i)
            midpoints.push_back((samples.u[i] + samples.u[i + 1]) / 2);
          error = interpolation_error(1, tag, samples, midpoints);
          if (error <= target * size)
            return "";
        }
      return error <= acceptable * size ? "" : missed(error, size, samples.u.size());
    }

    // Values and first derivatives from gmsh on the grid samples.u x samples.v; the twist x_uv
    // by differences of x_u along v (second order; gmsh's second derivatives are not available
    // for every kernel's surfaces).
    bool fill_grid(const int tag, ParametricSamples &samples, double &size)
    {
      const std::size_t   nu = samples.u.size(), nv = samples.v.size();
      std::vector<double> uv, xyz, derivatives;
      for (const double u : samples.u)
        for (const double v : samples.v)
          uv.push_back(u), uv.push_back(v);
      gmsh::model::getValue(2, tag, uv, xyz);
      gmsh::model::getDerivative(2, tag, uv, derivatives);
      if (!all_finite(xyz, 3 * nu * nv) || !all_finite(derivatives, 6 * nu * nv))
        return false;
      samples.data.assign(12 * nu * nv, 0.);
      for (std::size_t k = 0; k < nu * nv; ++k)
        for (unsigned int d = 0; d < 3; ++d)
          {
            samples.data[12 * k + d]     = xyz[3 * k + d];
            samples.data[12 * k + 3 + d] = derivatives[6 * k + d];
            samples.data[12 * k + 6 + d] = derivatives[6 * k + 3 + d];
          }
      for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j)
          {
            // Central differences inside, one-sided second-order ones at the ends.
            const std::size_t a = j == 0 ? 0 : (j + 1 == nv ? nv - 3 : j - 1);
            const double      h = samples.v[1] - samples.v[0];
            const double     *x_u = samples.data.data() + 3;
            for (unsigned int d = 0; d < 3; ++d)
              {
                const double f0 = x_u[12 * (i * nv + a) + d], f1 = x_u[12 * (i * nv + a + 1) + d],
                             f2 = x_u[12 * (i * nv + a + 2) + d];
                samples.data[12 * (i * nv + j) + 9 + d] =
                  j == 0 ? (-3 * f0 + 4 * f1 - f2) / (2 * h) : (j + 1 == nv ? (f0 - 4 * f1 + 3 * f2) / (2 * h) : (f2 - f0) / (2 * h));
              }
          }
      size = extent(xyz);
      return size > 0;
    }

    std::string sample_surface(const int tag, ParametricSamples &samples)
    {
      std::vector<double> min, max;
      if (!finite_bounds(2, tag, min, max))
        return "its parametrization has no finite range";
      unsigned int nu = 8, nv = 8;
      double       error = 0, size = 0;
      while (true)
        {
          samples.u = spaced(min[0], max[0], nu);
          samples.v = spaced(min[1], max[1], nv);
          if (!fill_grid(tag, samples, size))
            return "gmsh gives no finite values or derivatives of its parametrization, or one point";
          // Midway along u, along v and across: each tells which parameter needs more samples.
          std::vector<double> along_u, along_v, across;
          for (unsigned int i = 0; i <= nu; ++i)
            for (unsigned int j = 0; j <= nv; ++j)
              {
                const double u_mid = i < nu ? (samples.u[i] + samples.u[i + 1]) / 2 : 0;
                const double v_mid = j < nv ? (samples.v[j] + samples.v[j + 1]) / 2 : 0;
                if (i < nu)
                  along_u.insert(along_u.end(), {u_mid, samples.v[j]});
                if (j < nv)
                  along_v.insert(along_v.end(), {samples.u[i], v_mid});
                if (i < nu && j < nv)
                  across.insert(across.end(), {u_mid, v_mid});
              }
          const double error_u = interpolation_error(2, tag, samples, along_u);
          const double error_v = interpolation_error(2, tag, samples, along_v);
          const double error_c = interpolation_error(2, tag, samples, across);
          error                = std::max({error_u, error_v, error_c});
          if (error <= target * size)
            return "";
          // Across only: the twist is off, both need more.
          const bool across_only = error_u <= target * size && error_v <= target * size;
          const bool more_u      = (error_u > target * size || across_only) && nu < max_surface;
          const bool more_v      = (error_v > target * size || across_only) && nv < max_surface;
          const unsigned int next_u = more_u ? 2 * nu : nu, next_v = more_v ? 2 * nv : nv;
          if ((!more_u && !more_v) || (next_u + 1) * (next_v + 1) > max_grid)
            break;
          nu = next_u, nv = next_v;
        }
      return error <= acceptable * size ? "" : missed(error, size, samples.data.size() / 12);
    }
  } // namespace

  std::string sample_entity(const int dim, const int tag, ParametricSamples &samples)
  {
    try
      {
        return dim == 1 ? sample_curve(tag, samples) : sample_surface(tag, samples);
      }
    catch (...) // gmsh throws (or reports through an exception) for entities it cannot evaluate
      {
        return "gmsh cannot evaluate its parametrization";
      }
  }
} // namespace compliant
