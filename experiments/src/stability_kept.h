// A finished audit of `lamina stability` kept in its report's directory
// (DIR/renders/modelNN_audit.json) so that an interrupted sweep resumes without auditing that
// model again (the scene renders are kept as every experiment keeps renders, kept_renders.h).
// The file holds every cell and probe exactly (doubles to the last bit; non-finite values as the
// strings "inf", "-inf", "nan"), with the material and the sample count it was audited with: a
// resume taking it back for another material or sample count is refused on one line.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "lamina/experiments/stability.h"

namespace lamina::experiments {

/// "renders/modelNN_audit.json" under the report's directory, NN counting from 1.
std::filesystem::path keptAuditFile(std::size_t index);

/// Writes `model`, audited with `samples` per cell, to `path` (through a temporary file: a file
/// there is always whole).
void writeKeptAudit(const std::filesystem::path& path, const AuditedModel& model, int samples);

/// The audit in `path` if it is of `materialJson` with `samples` per cell; InputError naming the
/// file and the first that differs otherwise, or if the file is damaged.
AuditedModel readKeptAudit(const std::filesystem::path& path, const std::string& materialJson,
                           int samples);

}  // namespace lamina::experiments
