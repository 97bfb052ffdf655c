#include <mechanisms/jansen/jansen_link_lengths.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      constexpr double degree = M_PI / 180.;

      void check_triangle(const char *name, const double a, const double b, const double c)
      {
        if (!(a < b + c && b < a + c && c < a + b))
          throw std::invalid_argument(std::string("JansenLinkLengths: ternary link ") + name +
                                      " violates the triangle inequality (sides " +
                                      std::to_string(a) + ", " + std::to_string(b) + ", " +
                                      std::to_string(c) + ")");
      }
    } // namespace

    JansenLinkLengths paper_link_lengths()
    {
      JansenLinkLengths l;
      l.ea           = 193.96;
      l.ab           = 75.;
      l.bc           = 250.;
      l.bg           = 309.5;
      l.ce           = 207.5;
      l.de           = 200.5;
      l.cd           = 279.;
      l.eg           = 196.5;
      l.df           = 197.;
      l.fg           = 183.;
      l.gh           = 245.;
      l.fh           = 328.;
      l.ground_angle = 11.6 * degree;
      return l;
    }

    JansenLinkLengths jansen_original_link_lengths()
    {
      constexpr double scale = 5.;
      JansenLinkLengths l;
      l.ea           = scale * std::hypot(38., 7.8); // a, l
      l.ab           = scale * 15.;                  // m
      l.bc           = scale * 50.;                  // j
      l.bg           = scale * 61.9;                 // k
      l.ce           = scale * 41.5;                 // b
      l.de           = scale * 40.1;                 // d
      l.cd           = scale * 55.8;                 // e
      l.eg           = scale * 39.3;                 // c
      l.df           = scale * 39.4;                 // f
      l.fg           = scale * 36.7;                 // g
      l.gh           = scale * 49.;                  // i
      l.fh           = scale * 65.7;                 // h
      l.ground_angle = std::atan2(7.8, 38.);
      return l;
    }

    void validate(const JansenLinkLengths &lengths)
    {
      const std::vector<std::pair<const char *, double>> named = {
        {"EA", lengths.ea}, {"AB", lengths.ab}, {"BC", lengths.bc}, {"BG", lengths.bg},
        {"CE", lengths.ce}, {"DE", lengths.de}, {"CD", lengths.cd}, {"EG", lengths.eg},
        {"DF", lengths.df}, {"FG", lengths.fg}, {"GH", lengths.gh}, {"FH", lengths.fh}};
      for (const auto &[name, value] : named)
        if (!(std::isfinite(value) && value > 0.))
          throw std::invalid_argument(std::string("JansenLinkLengths: length ") + name +
                                      " must be a positive finite number, got " +
                                      std::to_string(value));
      if (!std::isfinite(lengths.ground_angle))
        throw std::invalid_argument("JansenLinkLengths: ground_angle (theta1) must be finite");
      check_triangle("CDE", lengths.cd, lengths.de, lengths.ce);
      check_triangle("FGH", lengths.fg, lengths.gh, lengths.fh);
    }
  } // namespace jansen
} // namespace compliant
