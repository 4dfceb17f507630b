#pragma once
// VTK's own error and warning output (coloured log lines on stderr) switched off for the whole
// process: every VTK call the code makes is checked and fails with its own one-line message.
namespace monosph {

void silence_vtk();

}  // namespace monosph
