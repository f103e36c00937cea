#include "vtkBoolSurfRankGather.h"

#include <vtkAlgorithm.h>
#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStaticCleanPolyData.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <numeric>
#include <string>
#include <utility>

namespace
{
/// What a rank sent for one (filter, port) last time, and on rank 0 what it gathered.
struct KeptInput
{
  vtkPolyData* Local = nullptr;
  vtkMTimeType LocalTime = 0;
  vtkSmartPointer<vtkPolyData> Gathered;
};

struct KeptInputs
{
  std::mutex Lock;
  std::map<std::pair<const vtkAlgorithm*, int>, KeptInput> Ports;
  std::map<const vtkAlgorithm*, unsigned long> Watched; // DeleteEvent observer tags
};

KeptInputs& Kept()
{
  static KeptInputs kept;
  return kept;
}

/// Forgets a filter's kept inputs when the filter is deleted (they hold whole surfaces).
void ForgetOnDelete(vtkAlgorithm* filter)
{
  KeptInputs& kept = Kept();
  if (kept.Watched.count(filter))
  {
    return;
  }
  vtkNew<vtkCallbackCommand> forget;
  forget->SetCallback(
    [](vtkObject* caller, unsigned long, void*, void*)
    {
      KeptInputs& all = Kept();
      std::lock_guard<std::mutex> guard(all.Lock);
      const auto* gone = static_cast<const vtkAlgorithm*>(caller);
      for (auto it = all.Ports.begin(); it != all.Ports.end();)
      {
        it = it->first.first == gone ? all.Ports.erase(it) : std::next(it);
      }
      all.Watched.erase(gone);
    });
  kept.Watched[filter] = filter->AddObserver(vtkCommand::DeleteEvent, forget);
}

/// The name of `attributes`' GlobalIds, now a plain array ("" when none). VTK's copies of
/// point and cell data leave the GlobalIds attribute out (and vtkStaticCleanPolyData crashed on
/// it), so the merge carries the ids as a plain array and marks them again at the end: the
/// gathered surface keeps the pieces' global ids (what Trace Surface Curves names the curves by
/// for the pieces, vtkBoolSurfCurvesMessage.h).
std::string UnmarkGlobalIds(vtkDataSetAttributes* attributes)
{
  vtkDataArray* ids = attributes->GetGlobalIds();
  if (!ids || !ids->GetName())
  {
    return std::string();
  }
  attributes->SetActiveAttribute(-1, vtkDataSetAttributes::GLOBALIDS);
  return ids->GetName();
}

void MarkGlobalIds(vtkDataSetAttributes* attributes, const std::string& name)
{
  if (!name.empty() && attributes->GetArray(name.c_str()))
  {
    attributes->SetActiveGlobalIds(name.c_str());
  }
}

/// The cells of pd in the order of their global ids `name` (pieces of a redistributed surface
/// come back in rank order; the ids, when present, give the input's order).
vtkSmartPointer<vtkPolyData> InGlobalIdOrder(vtkPolyData* pd, const std::string& name)
{
  vtkDataArray* ids = name.empty() ? nullptr : pd->GetCellData()->GetArray(name.c_str());
  if (!ids || ids->GetNumberOfTuples() != pd->GetNumberOfCells())
  {
    return pd;
  }
  std::vector<vtkIdType> order(pd->GetNumberOfCells());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(),
    order.end(),
    [ids](vtkIdType a, vtkIdType b) { return ids->GetTuple1(a) < ids->GetTuple1(b); });
  auto sorted = vtkSmartPointer<vtkPolyData>::New();
  sorted->SetPoints(pd->GetPoints());
  sorted->GetPointData()->ShallowCopy(pd->GetPointData());
  sorted->AllocateExact(pd->GetNumberOfCells(), pd->GetNumberOfCells() * 3);
  sorted->GetCellData()->CopyAllocate(pd->GetCellData(), pd->GetNumberOfCells());
  vtkNew<vtkIdList> points;
  for (vtkIdType c : order)
  {
    pd->GetCellPoints(c, points);
    const vtkIdType to = sorted->InsertNextCell(pd->GetCellType(c), points);
    sorted->GetCellData()->CopyData(pd->GetCellData(), c, to);
  }
  return sorted;
}

/// One polydata from the ranks' pieces (see the class comment).
vtkSmartPointer<vtkPolyData> Merge(const std::vector<vtkSmartPointer<vtkDataObject>>& pieces,
  vtkPolyData* own,
  bool surface)
{
  std::vector<vtkPolyData*> filled;
  for (size_t rank = 0; rank < pieces.size(); ++rank)
  {
    // Rank 0's own piece is its input object itself, so its caches keep their key.
    vtkPolyData* pd = rank == 0 && own ? own : vtkPolyData::SafeDownCast(pieces[rank]);
    if (pd && (pd->GetNumberOfCells() > 0 || pd->GetNumberOfPoints() > 0))
    {
      filled.push_back(pd);
    }
  }
  if (filled.empty())
  {
    return own ? vtkSmartPointer<vtkPolyData>(own) : vtkSmartPointer<vtkPolyData>::New();
  }
  if (filled.size() == 1)
  {
    return filled[0];
  }
  vtkNew<vtkAppendPolyData> append;
  for (vtkPolyData* pd : filled)
  {
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    piece->ShallowCopy(pd);
    piece->RemoveGhostCells();
    append->AddInputData(piece);
  }
  append->Update();
  vtkSmartPointer<vtkPolyData> merged = append->GetOutput();
  const std::string pointIds = UnmarkGlobalIds(merged->GetPointData());
  const std::string cellIds = UnmarkGlobalIds(merged->GetCellData());
  if (surface)
  {
    // Pieces of one surface repeat the points on their shared edges: merge exact duplicates
    // only, so distinct vertices that happen to be close stay apart.
    vtkNew<vtkStaticCleanPolyData> clean;
    clean->SetInputData(merged);
    clean->ToleranceIsAbsoluteOn();
    clean->SetAbsoluteTolerance(0.0);
    clean->ConvertLinesToPointsOff();
    clean->ConvertPolysToLinesOff();
    clean->ConvertStripsToPolysOff();
    clean->Update();
    merged = clean->GetOutput();
  }
  merged = InGlobalIdOrder(merged, cellIds);
  MarkGlobalIds(merged->GetPointData(), pointIds);
  MarkGlobalIds(merged->GetCellData(), cellIds);
  merged->GetFieldData()->ShallowCopy(filled[0]->GetFieldData());
  return merged;
}
} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfRankGather::vtkBoolSurfRankGather(vtkAlgorithm* filter,
  vtkInformationVector** inputVector,
  int ports,
  std::vector<int> surfacePorts)
{
  std::vector<vtkPolyData*> local(ports, nullptr);
  for (int p = 0; p < ports; ++p)
  {
    if (inputVector[p]->GetNumberOfInformationObjects() > 0)
    {
      local[p] = vtkPolyData::GetData(inputVector[p], 0);
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  this->Processes = controller ? controller->GetNumberOfProcesses() : 1;
  if (this->Processes <= 1)
  {
    this->Inputs.assign(local.begin(), local.end());
    return;
  }
  const int rank = controller->GetLocalProcessId();
  this->Here = rank == 0;
  this->Inputs.resize(ports);

  KeptInputs& kept = Kept();
  std::lock_guard<std::mutex> guard(kept.Lock);
  ForgetOnDelete(filter);
  // Gather again only when some rank's input changed (one small all-reduce otherwise).
  int changed = 0;
  for (int p = 0; p < ports; ++p)
  {
    auto found = kept.Ports.find({ filter, p });
    const vtkMTimeType time = local[p] ? local[p]->GetMTime() : 0;
    if (found == kept.Ports.end() || found->second.Local != local[p] ||
      found->second.LocalTime != time)
    {
      changed = 1;
    }
  }
  int anyChanged = 1;
  controller->AllReduce(&changed, &anyChanged, 1, vtkCommunicator::MAX_OP);
  for (int p = 0; p < ports; ++p)
  {
    KeptInput& entry = kept.Ports[{ filter, p }];
    if (anyChanged)
    {
      vtkSmartPointer<vtkPolyData> send = local[p];
      if (!send)
      {
        send = vtkSmartPointer<vtkPolyData>::New();
      }
      std::vector<vtkSmartPointer<vtkDataObject>> pieces;
      controller->Gather(send, pieces, 0);
      entry.Local = local[p];
      entry.LocalTime = local[p] ? local[p]->GetMTime() : 0;
      if (this->Here)
      {
        const bool surface =
          std::find(surfacePorts.begin(), surfacePorts.end(), p) != surfacePorts.end();
        entry.Gathered = Merge(pieces, local[p], surface);
        // An optional input absent everywhere stays absent.
        if (!local[p] && entry.Gathered->GetNumberOfPoints() == 0)
        {
          entry.Gathered = nullptr;
        }
      }
    }
    if (this->Here)
    {
      this->Inputs[p] = entry.Gathered;
    }
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkBoolSurfRankGather::Input(int port) const
{
  return port >= 0 && port < static_cast<int>(this->Inputs.size()) ? this->Inputs[port] : nullptr;
}
