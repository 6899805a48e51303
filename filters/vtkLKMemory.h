// The machine's memory, for filters that size a large allocation from their
// input or parameters (an image header, a sample count): asking for more than
// there is would end the program in std::bad_alloc, so they refuse first.
#ifndef vtkLKMemory_h
#define vtkLKMemory_h

#include <vtksys/SystemInformation.hxx>

#include <sstream>
#include <string>

namespace lkvtk
{
/// Total physical memory in bytes (0 when unknown).
inline double physicalMemoryBytes()
{
  vtksys::SystemInformation system;
  system.RunMemoryCheck();
  return static_cast<double>(system.GetTotalPhysicalMemory()) * 1024.0 * 1024.0; // MiB
}

/// True when `bytes` exceeds the machine's memory; `message` then reads
/// "X GB, more than this machine's memory (Y GB)".
inline bool exceedsMemory(double bytes, std::string& message)
{
  const double memory = physicalMemoryBytes();
  if (!(memory > 0.0) || bytes <= memory)
  {
    return false;
  }
  std::ostringstream os;
  os.precision(3);
  const double gb = bytes / 1e9;
  if (gb >= 1000.0) // whole gigabytes, not 1.2e+04
    os << static_cast<long long>(gb + 0.5);
  else
    os << gb;
  os << " GB, more than this machine's memory (" << memory / 1e9 << " GB)";
  message = os.str();
  return true;
}
} // namespace lkvtk

#endif
