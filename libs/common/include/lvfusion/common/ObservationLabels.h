#pragma once
// The sensor labels of what lvfusion adds to a log: the fused virtual scan
// (a CObservation2DRangeScan) and the model check's picture (a
// CObservationImage). One name each for the code that writes them and the
// code that finds them again (lvf-fuse reading a log fused before, lvf-map
// building the fused map); users pick them with rawlog-edit --keep-label.

namespace lvf::common
{
inline constexpr const char* kFusedScanLabel = "FUSED";
inline constexpr const char* kEvaluationImageLabel = "EVAL";
}  // namespace lvf::common
