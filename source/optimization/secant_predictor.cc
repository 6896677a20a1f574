#include <softopt/optimization/secant_predictor.h>

#include <algorithm>

namespace softopt
{
  std::map<double, SecantPredictor::Vector>
  SecantPredictor::predict(const Vector &X, const std::map<double, Vector> &states)
  {
    alpha = 0;
    if (previous.states.size() != states.size() || states.empty())
      return states;
    Vector step = X, secant = last.X;
    step -= last.X;
    secant -= previous.X;
    const double secant_norm2 = secant * secant;
    if (!(secant_norm2 > 0))
      return states;
    const double projection =
      std::clamp((step * secant) / secant_norm2, -max_alpha, max_alpha);

    std::map<double, Vector> predicted = states;
    for (auto &[load_factor, a] : predicted)
      {
        const auto a_previous = previous.states.find(load_factor);
        if (a_previous == previous.states.end())
          return states;
        // a_k + alpha (a_k - a_{k-1})
        a.sadd(1. + projection, -projection, a_previous->second);
      }
    alpha = projection;
    return predicted;
  }



  void
  SecantPredictor::accept(const Vector &X, const std::map<double, Vector> &states)
  {
    if (!last.states.empty())
      previous = std::move(last);
    last = {X, states};
  }



  const SecantPredictor::Design &
  SecantPredictor::last_design() const
  {
    return last;
  }



  const SecantPredictor::Design &
  SecantPredictor::previous_design() const
  {
    return previous;
  }



  void
  SecantPredictor::restore(const Design &previous_, const Design &last_)
  {
    previous = previous_;
    last     = last_;
    alpha    = 0;
  }



  double
  SecantPredictor::last_alpha() const
  {
    return alpha;
  }
} // namespace softopt
