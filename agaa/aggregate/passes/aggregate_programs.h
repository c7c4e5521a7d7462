#pragma once
// AGAA's programs by their names in the shader table (shaders/CMakeLists.txt), the names
// AggregateSettings::programs replaces them by, and which variant each pass runs.

#include "agaa/common/program_overrides.h"

#include <vector>

namespace agaa {

const NamedProgram& visibilityProgram();
const NamedProgram& clusterProgram(bool gbuffer); // the samples path clusters the G-buffer
const NamedProgram& generationProgram(bool emissive, bool int64, bool subgroup);
const NamedProgram& lightingProgram(bool gbuffer, bool emissive, bool shadows);
// The flagged pixels' per-sample shading: from the samples path's G-buffer (which holds its
// emissive), or from the accumulate path's per-sample material.
const NamedProgram& perSampleProgram(bool accumulate, bool emissive, bool shadows);
const NamedProgram& aggregatesViewProgram(); // --debug aggregates
// Every program above once, in the table's order.
std::vector<NamedProgram> aggregatePrograms();

// Refuses a replacement for a program AGAA does not run, by name (a misspelt name would
// otherwise replace nothing and time the shipping build): std::invalid_argument listing them.
void checkProgramOverrides(const ProgramOverrides& overrides);

} // namespace agaa
