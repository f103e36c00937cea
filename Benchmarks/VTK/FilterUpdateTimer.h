// Wall time of each filter's own execution inside one pipeline update, for the benchmarks of the
// stage filters. A user's edit updates the last filter of the chain once (ParaView updates the
// visible representation, pvpython's UpdatePipeline the active source); timing each stage by
// updating it on its own would add the executive's passes over the filters upstream of it to
// the edit. The filters' StartEvent and EndEvent bracket their RequestData, so observing them
// splits that one update into stages.
#ifndef boolsurf_FilterUpdateTimer_h
#define boolsurf_FilterUpdateTimer_h

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>

#include <sys/resource.h>

#include <chrono>
#include <vector>

namespace benchutil
{

/// Minor page faults of the process so far: memory touched for the first time since it was
/// mapped (fresh allocations), which an edit that reuses its buffers does not pay.
inline double ProcessMinorFaults()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_minflt);
}

class FilterUpdateTimer
{
public:
  /// Times `filters` (kept by the caller for the timer's lifetime); Milliseconds(k) is filter
  /// k's total execution time since the timer was made. `countFaults` also counts each
  /// filter's minor faults, at the cost of a system call per event (about 0.7 us here: eight
  /// per edit of a four-filter chain, which a small scene's edit should not be charged).
  explicit FilterUpdateTimer(const std::vector<vtkAlgorithm*>& filters, bool countFaults = true)
    : Filters(filters)
    , CountFaults(countFaults)
    , Started(filters.size())
    , Total(filters.size(), 0.0)
    , FaultsAtStart(filters.size(), 0.0)
    , Faults(filters.size(), 0.0)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(&FilterUpdateTimer::OnEvent);
    for (vtkAlgorithm* filter : this->Filters)
    {
      this->Tags.push_back(filter->AddObserver(vtkCommand::StartEvent, this->Callback));
      this->Tags.push_back(filter->AddObserver(vtkCommand::EndEvent, this->Callback));
    }
  }
  ~FilterUpdateTimer()
  {
    for (std::size_t k = 0; k < this->Filters.size(); ++k)
    {
      this->Filters[k]->RemoveObserver(this->Tags[2 * k]);
      this->Filters[k]->RemoveObserver(this->Tags[2 * k + 1]);
    }
  }
  FilterUpdateTimer(const FilterUpdateTimer&) = delete;
  FilterUpdateTimer& operator=(const FilterUpdateTimer&) = delete;

  double Milliseconds(std::size_t k) const { return this->Total[k]; }
  /// Minor page faults during filter k's executions (memory the process touched for the first
  /// time: buffers allocated anew rather than reused).
  double MinorFaults(std::size_t k) const { return this->Faults[k]; }

private:
  using Clock = std::chrono::steady_clock;

  static void OnEvent(vtkObject* caller, unsigned long event, void* self, void*)
  {
    auto* timer = static_cast<FilterUpdateTimer*>(self);
    const Clock::time_point now = Clock::now();
    const double faults = timer->CountFaults ? ProcessMinorFaults() : 0.0;
    for (std::size_t k = 0; k < timer->Filters.size(); ++k)
    {
      if (timer->Filters[k] != caller)
      {
        continue;
      }
      if (event == vtkCommand::StartEvent)
      {
        timer->Started[k] = now;
        timer->FaultsAtStart[k] = faults;
      }
      else
      {
        timer->Total[k] +=
          std::chrono::duration<double, std::milli>(now - timer->Started[k]).count();
        timer->Faults[k] += faults - timer->FaultsAtStart[k];
      }
    }
  }

  std::vector<vtkAlgorithm*> Filters;
  bool CountFaults = true;
  std::vector<Clock::time_point> Started;
  std::vector<double> Total;
  std::vector<double> FaultsAtStart;
  std::vector<double> Faults;
  std::vector<unsigned long> Tags;
  vtkNew<vtkCallbackCommand> Callback;
};

} // namespace benchutil

#endif
