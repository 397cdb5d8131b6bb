#pragma once
// The observer that keeps the time series (point_result.hpp's TimeSeries): one row per record.
#include "dynamics/point_result.hpp"
#include "dynamics/run_record.hpp"

namespace hmfnet {

class SeriesRecorder : public RunObserver {
 public:
  explicit SeriesRecorder(TimeSeries& series) : m_series(series) {}
  void on_record(const RunRecord& r) override {
    const Observables& o = *r.observed;
    m_series.t.push_back(r.t);
    // A run across replicas has its K per record from split_lanes (replica_lanes.hpp).
    m_series.K.push_back(r.K->front());
    m_series.R.insert(m_series.R.end(), o.R.begin(), o.R.end());
    m_series.energy.insert(m_series.energy.end(), o.energy.begin(), o.energy.end());
    m_series.momentum.insert(m_series.momentum.end(), o.momentum.begin(), o.momentum.end());
  }

 private:
  TimeSeries& m_series;
};

}  // namespace hmfnet
