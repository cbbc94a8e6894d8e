#include "PythonTrace.h"

#include "IntegrationValues.h"
#include "PictureValues.h"

#include "RiemannPictureSettingsDeclaration.h"
#include "SettingValues.h"

#include "RungeKutta.h"

#include "PipelineItem.h"
#include "StudioDocument.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannScene.h"

#include "vtkCamera.h"

#include <cctype>
#include <set>
#include <sstream>

namespace riemann
{
namespace studio
{
namespace
{
/// A Python identifier from an item's name ("Geodesics 1" -> "geodesics_1").
std::string Identifier(const std::string& name, std::set<std::string>& used)
{
  std::string id;
  for (char c : name)
  {
    id += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  }
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0])))
  {
    id = "item_" + id;
  }
  std::string unique = id;
  for (int n = 2; used.count(unique) || unique == "metric" || unique == "scene" ||
       unique == "camera" || unique == "picture" || unique == "riemann"; ++n)
  {
    unique = id + "_" + std::to_string(n);
  }
  used.insert(unique);
  return unique;
}

void WriteHeader(std::ostream& out)
{
  out << R"(#!/usr/bin/env python3
"""A Riemann Studio session, rebuilt with the RiemannVTK Python package.

Written by riemann-studio (File > Export > Python Script). Run it with the
Python that has Debian's VTK bindings (/usr/bin/python3) and the `riemann`
package on PYTHONPATH; it updates every filter of the session and, with
--output-dir, writes their outputs (.vtp / .vti, for ParaView).
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import vtkCamera

import riemann


def write(data, path):
    writer = vtkXMLImageDataWriter() if isinstance(data, vtkImageData) else vtkXMLPolyDataWriter()
    writer.SetFileName(path + (".vti" if isinstance(data, vtkImageData) else ".vtp"))
    writer.SetInputData(data)
    if not writer.Write():
        sys.exit("cannot write " + writer.GetFileName())


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--output-dir", help="write every item's output there")
args = parser.parse_args()

)";
}

void WriteMetric(std::ostream& out, const StudioDocument& document)
{
  out << "# The metric (the editor's text with the slider values applied) at time t.\n"
      << "metric = riemann.vtkRiemannMetric()\n"
      << "metric.SetTime(" << PythonNumber(document.Time()) << ")\n"
      << "if not metric.SetDefinition(" << PythonString(document.EffectiveMetricText())
      << (document.MetricDirectory().empty() ? std::string()
                                             : ", " + PythonString(document.MetricDirectory()))
      << "):\n"
      << "    sys.exit(metric.GetLastError())\n\n";
}

void WriteScene(std::ostream& out, const StudioDocument& document)
{
  vtkRiemannScene* scene = document.Scene();
  out << "# The scene (no definition: the default grid).\n"
      << "scene = riemann.vtkRiemannScene()\n";
  const std::string file = scene->GetDefinitionFile();
  if (!file.empty())
  {
    out << "if not scene.SetDefinitionFile(" << PythonString(file) << "):\n"
        << "    sys.exit(scene.GetLastError())\n";
  }
  else if (scene->HasDefinition())
  {
    out << "if not scene.SetDefinition(" << PythonString(scene->GetDefinition()) << "):\n"
        << "    sys.exit(scene.GetLastError())\n";
  }
  out << "\n";
}

void WriteObserver(std::ostream& out, const StudioDocument& document)
{
  vtkCamera* camera = document.Observer();
  vtkRiemannIntegrationSettings* rays = document.RaySettings();
  // The observer as its declared settings (vtkRiemannPictureSettings), as
  // `riemann render` and a scene's camera block name them.
  out << "# The observer (the inside view's camera) and its rays.\n"
      << "picture = riemann.vtkRiemannPictureSettings()\n";
  for (const std::string& line :
    riemann::SettingPythonLines(riemann::declared::vtkRiemannPictureSettings::Settings, "picture",
      CameraValues(camera)))
  {
    out << line << "\n";
  }
  out << "camera = vtkCamera()\n"
      << "picture.ApplyTo(camera)\n"
      << "width, height = " << document.ViewWidth() << ", " << document.ViewHeight() << "\n"
      << "use_scene_settings = " << (document.UseSceneSettings() ? "True" : "False") << "\n"
      << "ray_settings = riemann.vtkRiemannIntegrationSettings()\n";
  for (const std::string& line : IntegrationPython("ray_settings", rays))
  {
    out << line << "\n";
  }
  out << "\n";
}
}

std::string PythonScript(const StudioDocument& document)
{
  std::ostringstream out;
  WriteHeader(out);
  WriteMetric(out, document);
  WriteScene(out, document);
  WriteObserver(out, document);
  std::set<std::string> used;
  out << "# The pipeline items.\nitems = {}\n";
  for (const auto& item : document.Items())
  {
    const std::string name = item->Name().toStdString();
    const std::string var = Identifier(name, used);
    out << "\n# " << name << " (" << item->Kind() << ")\n";
    for (const std::string& line : item->PythonLines(var))
    {
      out << line << "\n";
    }
    out << var << ".Update()\n"
        << "items[" << PythonString(name) << "] = " << var << "\n";
  }
  out << R"(
if args.output_dir:
    os.makedirs(args.output_dir, exist_ok=True)
    for name, algorithm in items.items():
        for port in range(algorithm.GetNumberOfOutputPorts()):
            suffix = "" if port == 0 else "-%d" % port
            write(algorithm.GetOutputDataObject(port), os.path.join(args.output_dir, name + suffix))
for name, algorithm in items.items():
    data = algorithm.GetOutputDataObject(0)
    print("%s: %s with %d points" % (name, data.GetClassName(), data.GetNumberOfPoints()))
)";
  return out.str();
}
}
}
