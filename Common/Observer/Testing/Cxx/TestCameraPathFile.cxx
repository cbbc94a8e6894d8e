// CameraPathFile: the camera path's JSON, read, refused with the key's path,
// and written so that it reads back the same.
#include "CameraPathFile.h"

#include <gtest/gtest.h>

#include <string>

using riemann::CameraPathFile;
using riemann::CameraPathKind;
using riemann::Vec3;

namespace
{
std::string ErrorOf(const std::string& text)
{
  try
  {
    riemann::ParseCameraPathFile(text, "path.json");
  }
  catch (const riemann::CameraPathFileError& e)
  {
    return e.what();
  }
  return {};
}
} // namespace

TEST(CameraPathFile, ReadsBothKindsOfPath)
{
  const CameraPathFile geodesic = riemann::ParseCameraPathFile(
    R"({"path": "geodesic", "position": [0, 0, 3], "look_at": [0, 0, 0], "view_up": [0, 1, 0],
        "length": 4.5, "fov": 50, "time": 0.25, "description": "into the bump"})");
  EXPECT_EQ(geodesic.Settings.Kind, CameraPathKind::Geodesic);
  EXPECT_EQ(geodesic.Settings.Start.Position, Vec3(0, 0, 3));
  EXPECT_EQ(geodesic.Settings.Start.ViewUp, Vec3(0, 1, 0));
  EXPECT_EQ(geodesic.Settings.Length, 4.5);
  EXPECT_EQ(geodesic.Settings.Start.ViewAngle, 50.0);
  EXPECT_EQ(geodesic.TimeFrom, 0.25);
  EXPECT_EQ(geodesic.TimeTo, 0.25);

  const CameraPathFile spline = riemann::ParseCameraPathFile(
    R"({"path": "spline", "keys": [[0, 0, 3], [1, 0, 2], [0, 1, 1]], "step": 0.01, "time": [0, 0.5]})");
  EXPECT_EQ(spline.Settings.Kind, CameraPathKind::Spline);
  ASSERT_EQ(spline.Settings.Keys.size(), 3u);
  EXPECT_EQ(spline.Settings.Keys[2], Vec3(0, 1, 1));
  EXPECT_EQ(spline.Settings.Step, 0.01);
  EXPECT_EQ(spline.TimeTo, 0.5);

  // Written and read back: the same settings.
  for (const CameraPathFile& file : { geodesic, spline })
  {
    const CameraPathFile again = riemann::ParseCameraPathFile(riemann::CameraPathFileText(file));
    EXPECT_EQ(again.Settings.Kind, file.Settings.Kind);
    EXPECT_EQ(again.Settings.Start.Position, file.Settings.Start.Position);
    EXPECT_EQ(again.Settings.Start.LookAt, file.Settings.Start.LookAt);
    EXPECT_EQ(again.Settings.Start.ViewUp, file.Settings.Start.ViewUp);
    EXPECT_EQ(again.Settings.Start.ViewAngle, file.Settings.Start.ViewAngle);
    EXPECT_EQ(again.Settings.Keys, file.Settings.Keys);
    EXPECT_EQ(again.Settings.Length, file.Settings.Length);
    EXPECT_EQ(again.Settings.Step, file.Settings.Step);
    EXPECT_EQ(again.TimeFrom, file.TimeFrom);
    EXPECT_EQ(again.TimeTo, file.TimeTo);
  }
}

TEST(CameraPathFile, BadFilesAreRefusedNamingTheKey)
{
  EXPECT_NE(ErrorOf("{").find("path.json"), std::string::npos);
  EXPECT_NE(ErrorOf(R"({"position": [0, 0, 1]})").find("missing required key \"path\""),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "helix"})").find("path.json.path: unknown path \"helix\""),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "geodesic", "position": [0, 0], "look_at": [0, 0, 0], "length": 1})")
              .find("path.json.position: expected [x, y, z]"),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "geodesic", "position": [0, 0, 1], "look_at": [0, 0, 0], "length": -1})")
              .find("path.json.length: expected a positive number"),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "spline", "keys": [[0, 0, 1]]})")
              .find("path.json.keys: expected at least 2 key positions"),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "spline", "keys": [[0, 0, 1], [0, "a", 0]]})")
              .find("path.json.keys[1][1]"),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "spline", "keys": [[0, 0, 1], [1, 0, 0]], "length": 2})")
              .find("path.json.length"),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "spline", "keys": [[0, 0, 1], [1, 0, 0]], "speed": 2})")
              .find("unknown key \"speed\""),
    std::string::npos);
  EXPECT_NE(ErrorOf(R"({"path": "spline", "keys": [[0, 0, 1], [1, 0, 0]], "time": [0]})")
              .find("path.json.time: expected t or [t0, t1]"),
    std::string::npos);
}
