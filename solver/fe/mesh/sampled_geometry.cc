#include "mesh/sampled_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    Vector3 minus(const Vector3 &a, const Vector3 &b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
    double  dot(const Vector3 &a, const Vector3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    void    add(Vector3 &to, const double factor, const double *from)
    {
      for (unsigned int d = 0; d < 3; ++d)
        to[d] += factor * from[d];
    }

    // The cubic Hermite basis on [0, 1] and its first two derivatives: value[end][order] takes
    // the value at the end, slope[end][order] the derivative there.
    struct Hermite
    {
      double value[2][3], slope[2][3];
      explicit Hermite(const double s)
        : value{{2 * s * s * s - 3 * s * s + 1, 6 * s * s - 6 * s, 12 * s - 6},
                {-2 * s * s * s + 3 * s * s, -6 * s * s + 6 * s, -12 * s + 6}}
        , slope{{s * s * s - 2 * s * s + s, 3 * s * s - 4 * s + 1, 6 * s - 4},
                {s * s * s - s * s, 3 * s * s - 2 * s, 6 * s - 2}}
      {}
    };

    // The interval [u_i, u_i+1] holding u (clamped into the samples' range), and u's place in it.
    unsigned int locate(const std::vector<double> &u, double &x, double &s, double &h)
    {
      x                    = std::clamp(x, u.front(), u.back());
      const auto   above   = std::upper_bound(u.begin(), u.end(), x);
      unsigned int i       = std::distance(u.begin(), above);
      i                    = std::min<unsigned int>(std::max(i, 1u), u.size() - 1) - 1;
      h                    = u[i + 1] - u[i];
      s                    = (x - u[i]) / h;
      return i;
    }

    // A ball holding the samples [i0, i1] x [j0, j1].
    template <class Sample>
    void bound(const Sample &sample, const unsigned int i0, const unsigned int i1, const unsigned int j0,
               const unsigned int j1, Vector3 &centre, double &radius)
    {
      centre          = {{0, 0, 0}};
      const double n  = (i1 - i0 + 1.) * (j1 - j0 + 1.);
      for (unsigned int i = i0; i <= i1; ++i)
        for (unsigned int j = j0; j <= j1; ++j)
          add(centre, 1. / n, sample(i, j).data());
      radius = 0;
      for (unsigned int i = i0; i <= i1; ++i)
        for (unsigned int j = j0; j <= j1; ++j)
          radius = std::max(radius, std::sqrt(dot(minus(sample(i, j), centre), minus(sample(i, j), centre))));
    }
  } // namespace

  SampledPoint evaluate(const ParametricSamples &samples, double u, double v)
  {
    SampledPoint result;
    double       su, hu;
    const unsigned int i = locate(samples.u, u, su, hu);
    const Hermite      bu(su);
    const double      *data = samples.data.data();
    if (!samples.is_surface())
      {
        Vector3     *out[3]   = {&result.x, &result.x_u, &result.x_uu};
        const double scale[3] = {1, 1 / hu, 1 / (hu * hu)};
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int a = 0; a < 2; ++a)
            {
              const double *at = data + 6 * (i + a);
              add(*out[k], bu.value[a][k] * scale[k], at);
              add(*out[k], bu.slope[a][k] * hu * scale[k], at + 3);
            }
        return result;
      }
    double             sv, hv;
    const unsigned int j = locate(samples.v, v, sv, hv);
    const Hermite      bv(sv);
    const unsigned int nv = samples.v.size();
    // (order in u, order in v) of each output.
    const unsigned int orders[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    Vector3 *out[6] = {&result.x, &result.x_u, &result.x_v, &result.x_uu, &result.x_uv, &result.x_vv};
    for (unsigned int k = 0; k < 6; ++k)
      {
        const unsigned int ku = orders[k][0], kv = orders[k][1];
        const double       scale = (ku == 0 ? 1 : ku == 1 ? 1 / hu : 1 / (hu * hu)) * (kv == 0 ? 1 : kv == 1 ? 1 / hv : 1 / (hv * hv));
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            {
              const double *at = data + 12 * ((i + a) * nv + j + b);
              add(*out[k], scale * bu.value[a][ku] * bv.value[b][kv], at);
              add(*out[k], scale * hu * bu.slope[a][ku] * bv.value[b][kv], at + 3);
              add(*out[k], scale * hv * bu.value[a][ku] * bv.slope[b][kv], at + 6);
              add(*out[k], scale * hu * hv * bu.slope[a][ku] * bv.slope[b][kv], at + 9);
            }
      }
    return result;
  }

  SampledShape::SampledShape(ParametricSamples samples)
    : data(std::move(samples))
  {
    const unsigned int nu = data.u.size(), nv = std::max<std::size_t>(data.v.size(), 1);
    if (nu < 2 || (data.is_surface() && nv < 2) || data.data.size() != std::size_t(nu) * nv * data.n_values())
      throw std::invalid_argument("SampledShape: inconsistent samples");
    // Blocks of about 64 samples: the search visits only blocks whose ball may hold a closer one.
    const unsigned int step_u = data.is_surface() ? 8 : 64, step_v = data.is_surface() ? 8 : 1;
    const auto         at     = [this](const unsigned int i, const unsigned int j) { return sample(i, j); };
    for (unsigned int i0 = 0; i0 + 1 < nu; i0 += step_u)
      for (unsigned int j0 = 0; j0 + 1 < nv || (j0 == 0 && nv == 1); j0 += step_v)
        {
          Block block{i0, std::min(i0 + step_u, nu - 1), j0, std::min(j0 + step_v, nv - 1), {}, 0};
          bound(at, block.i0, block.i1, block.j0, block.j1, block.centre, block.radius);
          blocks.push_back(block);
        }
  }

  Vector3 SampledShape::sample(const unsigned int i, const unsigned int j) const
  {
    const double *x = data.data.data() + data.n_values() * (i * std::max<std::size_t>(data.v.size(), 1) + j);
    return {{x[0], x[1], x[2]}};
  }

  Vector3 SampledShape::closest_point(const Vector3 &p, std::array<double, 2> *parameters) const
  {
    // The closest sample: first the block whose centre is nearest sets a bound, then every block
    // whose ball comes closer than the bound is searched.
    double       best = std::numeric_limits<double>::max();
    unsigned int best_i = 0, best_j = 0;
    const auto   search = [&](const Block &block) {
      for (unsigned int i = block.i0; i <= block.i1; ++i)
        for (unsigned int j = block.j0; j <= block.j1; ++j)
          {
            const Vector3 r        = minus(sample(i, j), p);
            const double  distance = dot(r, r);
            if (distance < best)
              best = distance, best_i = i, best_j = j;
          }
    };
    std::size_t nearest = 0;
    double      nearest_distance = std::numeric_limits<double>::max();
    for (std::size_t b = 0; b < blocks.size(); ++b)
      {
        const Vector3 r = minus(blocks[b].centre, p);
        if (dot(r, r) < nearest_distance)
          nearest_distance = dot(r, r), nearest = b;
      }
    search(blocks[nearest]);
    for (std::size_t b = 0; b < blocks.size(); ++b)
      {
        const double reach = std::sqrt(dot(minus(blocks[b].centre, p), minus(blocks[b].centre, p))) - blocks[b].radius;
        if (b != nearest && (reach <= 0 || reach * reach < best))
          search(blocks[b]);
      }
    double u = data.u[best_i], v = data.is_surface() ? data.v[best_j] : 0;
    newton(p, u, v);
    if (parameters)
      *parameters = {{u, v}};
    return evaluate(data, u, v).x;
  }

  // Newton on the squared distance in the parameters, from the closest sample: the full Hessian
  // where it is positive definite, else Gauss-Newton (near a collapsed edge, damped); steps halved
  // until the distance falls, parameters clamped to the samples' range.
  void SampledShape::newton(const Vector3 &p, double &u, double &v) const
  {
    const bool   surface = data.is_surface();
    const double range_u = data.u.back() - data.u.front();
    const double range_v = surface ? data.v.back() - data.v.front() : 1;
    SampledPoint at      = evaluate(data, u, v);
    Vector3      r       = minus(at.x, p);
    double       current = dot(r, r);
    for (unsigned int iteration = 0; iteration < 40; ++iteration)
      {
        const double g[2] = {dot(at.x_u, r), surface ? dot(at.x_v, r) : 0};
        double       h[3] = {dot(at.x_u, at.x_u), surface ? dot(at.x_u, at.x_v) : 0, surface ? dot(at.x_v, at.x_v) : 1};
        const double full[3] = {h[0] + dot(at.x_uu, r), h[1] + dot(at.x_uv, r), h[2] + (surface ? dot(at.x_vv, r) : 0)};
        if (full[0] > 0 && full[0] * full[2] - full[1] * full[1] > 1e-12 * h[0] * h[2])
          std::copy(full, full + 3, h);
        const double damping = 1e-12 * (h[0] + h[2]);
        h[0] += damping, h[2] += damping;
        const double det = h[0] * h[2] - h[1] * h[1];
        if (!(det > 0))
          return;
        double du = -(h[2] * g[0] - h[1] * g[1]) / det, dv = surface ? -(h[0] * g[1] - h[1] * g[0]) / det : 0;
        double taken_u = 0, taken_v = 0;
        bool   improved = false;
        for (unsigned int halving = 0; halving < 30 && !improved; ++halving, du /= 2, dv /= 2)
          {
            const double new_u = std::clamp(u + du, data.u.front(), data.u.back());
            const double new_v = surface ? std::clamp(v + dv, data.v.front(), data.v.back()) : 0;
            const SampledPoint trial   = evaluate(data, new_u, new_v);
            const Vector3      new_r   = minus(trial.x, p);
            if (dot(new_r, new_r) <= current)
              {
                improved = true;
                taken_u = new_u - u, taken_v = new_v - v;
                u = new_u, v = new_v, at = trial, r = new_r, current = dot(new_r, new_r);
              }
          }
        // Newton converges quadratically: after a step of 1e-12 the next would be round-off.
        if (!improved || (std::abs(taken_u) <= 1e-12 * range_u && std::abs(taken_v) <= 1e-12 * range_v))
          return;
      }
  }

  Vector3 SampledShape::project_average(const std::vector<Vector3> &points, const std::vector<double> &weights) const
  {
    Vector3 average = {{0, 0, 0}};
    for (std::size_t k = 0; k < points.size(); ++k)
      add(average, weights[k], points[k].data());
    return closest_point(average);
  }
} // namespace compliant
