#include <softopt/optimization/secant_predictor.h>

#include <algorithm>

namespace softopt
{
  std::optional<SecantPredictor::Prediction>
  SecantPredictor::predict(const Vector &X, const std::map<double, Vector> &states) const
  {
    if (states.empty() || previous.states.size() != states.size())
      return std::nullopt;
    Vector step = X, secant = X_last;
    step -= X_last;
    secant -= previous.X;
    const double secant_norm2 = secant * secant;
    if (!(secant_norm2 > 0))
      return std::nullopt;

    Prediction prediction{states,
                          std::clamp((step * secant) / secant_norm2,
                                     -max_alpha,
                                     max_alpha)};
    for (auto &[load_factor, a] : prediction.states)
      {
        const auto a_previous = previous.states.find(load_factor);
        if (a_previous == previous.states.end())
          return std::nullopt;
        // a_k + alpha (a_k - a_{k-1})
        a.sadd(1. + prediction.alpha, -prediction.alpha, a_previous->second);
      }
    return prediction;
  }



  void
  SecantPredictor::accept(const Vector &X, const std::map<double, Vector> &last_states)
  {
    if (X_last.size() > 0 && !last_states.empty())
      previous = {X_last, last_states};
    X_last = X;
  }



  const SecantPredictor::Vector &
  SecantPredictor::last_positions() const
  {
    return X_last;
  }



  const SecantPredictor::Design &
  SecantPredictor::previous_design() const
  {
    return previous;
  }



  void
  SecantPredictor::restore(const Vector &last_positions, const Design &previous_design)
  {
    X_last   = last_positions;
    previous = previous_design;
  }
} // namespace softopt
