/**
 * @brief   what one MPI rank spent on a stage run on its piece: wall time per step and bytes
 *          per message, written on the stage's output
 *
 * A stage run on pieces (Surface Arrangement, Label Arrangement Cells, Surface Boolean) writes
 * its rank's own figures as field arrays of its output: StageTimes (milliseconds, one
 * component per step, as the one-rank filters name theirs) and PieceBytes (bytes, a
 * <message>Sent and a <message>Received component per message). Each rank's output carries
 * its own, so a script reads them per rank (Benchmarks/ParaView/mpi_scale.py): how the time and
 * the traffic of an update divide among ranks is what the distributed stages are for.
 *
 * Bytes are the payload a rank hands to or gets from the controller (each buffer with its
 * length), counted once per receiving rank, as point-to-point messages would carry them; a
 * broadcast or an all-gather is counted as if the root sent to every rank.
 */
#ifndef vtkBoolSurfPieceCosts_h
#define vtkBoolSurfPieceCosts_h

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

struct PieceCosts
{
  struct Step
  {
    std::string Name;
    double Milliseconds = 0;
  };
  struct Message
  {
    std::string Name;
    std::size_t Sent = 0, Received = 0;
  };
  std::vector<Step> Times;
  std::vector<Message> Bytes;

  void AddTime(const char* name, double milliseconds)
  {
    this->Times.push_back({ name, milliseconds });
  }
  void AddBytes(const char* name, std::size_t sent, std::size_t received)
  {
    this->Bytes.push_back({ name, sent, received });
  }
};

/// Milliseconds between the calls of Lap(), the first from construction.
class PieceStopwatch
{
public:
  double Lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - this->Last).count();
    this->Last = now;
    return ms;
  }

private:
  std::chrono::steady_clock::time_point Last = std::chrono::steady_clock::now();
};

/// Bytes of a message of `values` 64-bit numbers sent with its length.
inline std::size_t WireBytes(std::size_t values)
{
  return (values + 1) * sizeof(long long);
}

/// Writes StageTimes (when `costs` has times) and PieceBytes (when it has messages) to
/// `output`'s field data, replacing arrays of those names.
void WritePieceCosts(const PieceCosts& costs, vtkPolyData* output);

/// The costs of a stage that sends nothing of its own on pieces (Label Arrangement Cells,
/// Surface Boolean): its wall time as Total, and its decision to run on pieces (two all-reduces
/// of one number, vtkBoolSurfAlgorithm) as the message Decision. Replaces the arrays its input
/// passed on.
void WriteLocalStageCosts(double milliseconds, vtkPolyData* output);

}

#endif
