// Fuel + lambda x time with an engine setting per step (Sotnikova 2009) over the physics of
// weather.hpp, on one forecast frame.
#pragma once

#include <utility>
#include <vector>

#include "weather.hpp"

namespace seaway {

// Sotnikova 2009's fuel: each step's engine setting is chosen from `settings_kn` (calm-water speeds)
// to minimise fuel + lambda x time, fuel burnt at rate_t_per_h per hour at each setting. Sweeping
// lambda (tonnes per hour of passage) traces the time-fuel trade-off; lambda = 0 is the least
// fuel. The weather is the forecast at departure (the label is fuel + lambda x time, not time,
// so the time a step starts is not known during the search).
class FuelLagrangian {
 public:
  static constexpr Capabilities caps = on_one_frame;
  FuelLagrangian(const WeatherTime& physics, std::vector<double> settings_kn,
                 std::vector<double> rate_t_per_h, double lambda, double best_extra_kn)
      : physics_(physics), settings_(std::move(settings_kn)), rate_(std::move(rate_t_per_h)),
        lambda_(lambda) {
    min_rate_ = inf;  // cheapest possible t/km: some setting at its fastest attainable speed
    for (std::size_t s = 0; s < settings_.size(); ++s)
      min_rate_ = std::min(min_rate_, (rate_[s] + lambda_) / (km_per_nm * (settings_[s] + best_extra_kn)));
  }

  StepBounds bounds(const Passability&) const { return {min_rate_, inf, true}; }

  template <class Cell>
  double operator()(std::int64_t v, std::int64_t w, int o, double r_km, double, Cell&&) const {
    return best(v, w, o, r_km).cost;
  }

  struct Choice {
    double cost = inf, hours = inf, fuel_t = inf;
    int setting = -1;
  };
  Choice best(std::int64_t v, std::int64_t w, int o, double r_km) const {
    Choice c;
    for (std::size_t s = 0; s < settings_.size(); ++s) {
      const double sog = physics_.speed_over_ground(v, w, o, 0.0, settings_[s]);
      if (sog <= 0) continue;
      const double hours = r_km / km_per_nm / sog, cost = (rate_[s] + lambda_) * hours;
      if (cost < c.cost) c = {cost, hours, rate_[s] * hours, int(s)};
    }
    return c;
  }

 private:
  const WeatherTime& physics_;
  std::vector<double> settings_, rate_;
  double lambda_, min_rate_;
};

}  // namespace seaway
