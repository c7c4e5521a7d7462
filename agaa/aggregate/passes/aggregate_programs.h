#pragma once
// AGAA's programs by their names in the shader table (shaders/CMakeLists.txt), the names
// AggregateSettings::programs replaces them by, and which variant each pass runs: each is looked up
// by name in the table's generated index, so the table is the one list of them.

#include "agaa/common/program_overrides.h"

#include <vector>

namespace agaa {

NamedProgram visibilityProgram();
NamedProgram clusterProgram(bool gbuffer); // the samples path clusters the G-buffer
NamedProgram generationProgram(bool emissive, bool int64, bool subgroup);
NamedProgram lightingProgram(bool gbuffer, bool emissive, bool shadows);
// The flagged pixels' per-sample shading: from the samples path's G-buffer (which holds its
// emissive), or from the accumulate path's per-sample material.
NamedProgram perSampleProgram(bool accumulate, bool emissive, bool shadows);
NamedProgram aggregatesViewProgram(); // --debug aggregates
// Every AGAA program of the shipping table, in its order.
std::vector<NamedProgram> aggregatePrograms();

// Refuses a replacement for a program AGAA does not run, by name (a misspelt name would
// otherwise replace nothing and time the shipping build): std::invalid_argument listing them.
void checkProgramOverrides(const ProgramOverrides& overrides);

} // namespace agaa
