#include "output/vtk_quiet.hpp"

#include <vtkLogger.h>
#include <vtkObject.h>

namespace monosph {

void silence_vtk() {
  vtkObject::GlobalWarningDisplayOff();  // vtkErrorMacro / vtkWarningMacro print nothing
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

}  // namespace monosph
