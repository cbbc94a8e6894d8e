// VTK's messages as one plain sentence (RiemannVtkMessages.h): no source
// path of VTK's build, no object address, no colours, one line.
#include "RiemannVtkMessages.h"

#include <gtest/gtest.h>

TEST(VtkMessages, LocationAndAddressAreDropped)
{
  EXPECT_EQ(riemann::PlainVtkMessage("ERROR: In ./IO/XML/vtkXMLReader.cxx, line 521\n"
                                     "vtkXMLPolyDataReader (0x5643a2035310): Error parsing input "
                                     "file.  ReadXMLInformation aborting.\n\n"),
    "vtkXMLPolyDataReader: Error parsing input file.  ReadXMLInformation aborting.");
  EXPECT_EQ(riemann::PlainVtkMessage("Warning: In vtkSTLReader.cxx, line 3\nvtkSTLReader "
                                     "(0x1): two\nlines"),
    "vtkSTLReader: two lines");
}

TEST(VtkMessages, TheCallersClassWhereTheTextNamesNone)
{
  EXPECT_EQ(riemann::PlainVtkMessage("cannot open the file\n", "vtkOBJReader"),
    "vtkOBJReader: cannot open the file");
  EXPECT_EQ(riemann::PlainVtkMessage("plain words"), "plain words");
  EXPECT_EQ(riemann::PlainVtkMessage("  \n"), "");
  EXPECT_EQ(riemann::PlainVtkMessage("\033[0m\033[31mvtkFoo (0xdead): red\033[0m"), "vtkFoo: red");
}

TEST(VtkMessages, AnsiEscapesAreRemoved)
{
  EXPECT_EQ(riemann::WithoutAnsiEscapes("\033[0m\033[31mERR|\033[0m text"), "ERR| text");
  EXPECT_EQ(riemann::WithoutAnsiEscapes("no escapes"), "no escapes");
}
