// riemann-studio driven with QtTest: the real window under xvfb-run (Mesa
// llvmpipe), each slot one feature of the app, checked against the
// toolkit's own answers (the same classes the app is built on).
#include "RiemannIntegrationSettingsDeclaration.h"
#include "HelpMenu.h"
#include "ColorMaps.h"
#include "InsideView.h"
#include "ItemDisplay.h"
#include "OutputDisplay.h"
#include "SpreadsheetView.h"
#include "MetricEditor.h"
#include "OutsideView.h"
#include "ParameterPanel.h"
#include "PipelineBrowser.h"
#include "IntegrationValues.h"
#include "PipelineItems.h"
#include "ProjectFile.h"
#include "ProjectSession.h"
#include "PropertiesPanel.h"
#include "StudioDocument.h"
#include "AnimationExport.h"
#include "JobRunner.h"
#include "PythonShell.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h"
#include "StudioMainWindow.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayBundle.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkCamera.h"
#include "vtkProbeFilter.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkAssembly.h"
#include "vtkCoordinate.h"
#include "vtkHandleWidget.h"
#include "vtkImageData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp3DCollection.h"
#include "vtkRenderer.h"
#include "vtkLookupTable.h"
#include "vtkScalarBarActor.h"
#include "vtkWeakPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <atomic>
#include <chrono>
#include <thread>
#include <QAction>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QUndoStack>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProcess>
#include <QSignalSpy>
#include <QPushButton>
#include <QSlider>
#include <QDockWidget>
#include <QTableWidget>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QTimer>
#include <QWheelEvent>
#include <QTemporaryDir>
#include <QtTest/QtTest>

#include <array>
#include <cmath>
#include <memory>

using namespace riemann::studio;

namespace
{
/// A job that records, on its worker thread, its own reference count when
/// it starts and again once the test lets it go on, after the caller's
/// scope that started it has ended: equal when nothing on the GUI thread
/// kept, registered or dropped a reference to the running algorithm
/// (JobRunner.h: VTK's garbage collector is not thread-safe, and a caller's
/// reference dropped while the job ran freed it).
class ReferenceProbe : public vtkPolyDataAlgorithm
{
public:
  static ReferenceProbe* New();
  vtkTypeMacro(ReferenceProbe, vtkPolyDataAlgorithm);
  std::atomic<int> Before{ -1 };
  std::atomic<int> After{ -1 };
  std::atomic<bool> Entered{ false };
  std::atomic<bool> GoOn{ false };

protected:
  ReferenceProbe() { this->SetNumberOfInputPorts(0); }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override
  {
    this->Before = this->GetReferenceCount();
    this->Entered = true;
    for (int waited = 0; !this->GoOn && waited < 10000; ++waited)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    this->After = this->GetReferenceCount();
    return 1;
  }
};
vtkStandardNewMacro(ReferenceProbe);
}

namespace
{
/// A window as a user gets it, shown and settled (jobs done, views drawn).
/// The inside view is kept small, and unless `defaultRays` its rays short
/// and coarse (the inside view's own settings instead of the scene's): Mesa's
/// llvmpipe traces the default scene at about 20,000 pixels a second here.
std::unique_ptr<StudioMainWindow> OpenWindow(bool defaultRays = false)
{
  auto window = std::make_unique<StudioMainWindow>();
  window->Inside()->setFixedSize(240, 180);
  if (!defaultRays)
  {
    vtkRiemannIntegrationSettings* rays = window->Document()->RaySettings();
    rays->SetInitialIntegrationStep(0.06);
    rays->SetMaximumPropagation(15.0);
    rays->SetMaximumNumberOfSteps(300);
    window->Document()->SetUseSceneSettings(false);
  }
  window->resize(1100, 700);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get()))
  {
    return nullptr;
  }
  window->Settle();
  return window;
}

/// Fraction of pixels that differ between two pictures of the same size.
double DifferentPixels(const QImage& a, const QImage& b)
{
  if (a.size() != b.size())
  {
    return 1.0;
  }
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  long differing = 0;
  for (int row = 0; row < x.height(); ++row)
  {
    const QRgb* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    const QRgb* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
    for (int column = 0; column < x.width(); ++column)
    {
      differing += p[column] != q[column];
    }
  }
  return static_cast<double>(differing) / (x.width() * x.height());
}

/// Number of distinct colours (a drawn view has many; a cleared one, one).
int DistinctColors(const QImage& image)
{
  QSet<QRgb> colors;
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  for (int row = 0; row < rgb.height(); row += 3)
  {
    for (int column = 0; column < rgb.width(); column += 3)
    {
      colors.insert(rgb.pixel(column, row));
    }
  }
  return colors.size();
}

QString DataFile(const QString& relative)
{
  const QByteArray dir = qgetenv("RIEMANN_DATA_DIR");
  return (dir.isEmpty() ? QStringLiteral(RIEMANN_TEST_DATA_DIR) : QString::fromLocal8Bit(dir)) + "/" +
    relative;
}

/// A scene quick to trace on llvmpipe (short coarse rays, two spheres and a
/// checker floor) with an inline metric that has a parameter.
QString WriteQuickScene(const QTemporaryDir& folder)
{
  const QString path = folder.filePath("quick-scene.json");
  QFile file(path);
  if (file.open(QIODevice::WriteOnly))
  {
    file.write(R"json({
  "metric": {"type": "graph", "parameters": {"a": 0.8},
             "gaussians": [{"amplitude": 1, "center": [0, 0, 0], "sigma": 0.6}]},
  "camera": {"position": [0, 0.5, 4], "look_at": [0, 0, 0], "view_up": [0, 1, 0], "fov": 50},
  "integrator": {"method": "rk4", "step": 0.08, "max_steps": 200, "max_length": 12},
  "objects": [
    {"type": "plane", "point": [0, -1.5, 0], "normal": [0, 1, 0],
     "material": {"type": "checker", "color": [0.9, 0.9, 0.88], "color2": [0.2, 0.25, 0.3], "size": 1}},
    {"type": "sphere", "center": [0, 0, -2], "radius": 1, "material": {"type": "solid", "color": [0.85, 0.2, 0.15]}},
    {"type": "sphere", "center": [1.5, 0, 0], "radius": 0.5, "material": {"type": "solid", "color": [0.2, 0.5, 0.9]}}
  ]
})json");
  }
  return path;
}

/// Export the session as a Python script (session.py in `folder`) and run
/// it with /usr/bin/python3 --output-dir folder/out: true when it exits with
/// 0; `output` holds what it printed (or why it could not run).
bool RunExportedScript(StudioMainWindow& window, const QTemporaryDir& folder, QString& output)
{
  const QString script = folder.filePath("session.py");
  output = window.ExportPythonScript(script);
  if (!output.isEmpty())
  {
    return false;
  }
  QProcess python;
  python.start("/usr/bin/python3", { script, "--output-dir", folder.filePath("out") });
  const bool finished = python.waitForFinished(120000);
  output = QString::fromUtf8(python.readAllStandardOutput() + python.readAllStandardError());
  return finished && python.exitCode() == 0;
}

bool WaitForJobs(StudioMainWindow& window, int milliseconds = 60000)
{
  QElapsedTimer timer;
  timer.start();
  while (window.Document()->Jobs()->NumberOfRunningJobs() > 0 && timer.elapsed() < milliseconds)
  {
    QTest::qWait(20);
  }
  return window.Document()->Jobs()->NumberOfRunningJobs() == 0;
}

bool ViewHasProp(OutsideView* view, vtkProp* prop)
{
  vtkPropCollection* props = view->Renderer()->GetViewProps();
  return props->IsItemPresent(prop) != 0;
}
}

class TestStudio : public QObject
{
  Q_OBJECT
private Q_SLOTS:
  void WindowOpensWithDefaultScene();
  void SyntaxErrorShowsColumnAndKeepsPicture();
  void SliderChangesViewWithoutRecompiling();
  void GeodesicItemAddsPolylines();
  void PickedPixelShowsBundleRay();
  void ProjectRoundTrip();
  void CancelledJobLeavesAppResponsive();
  void JobsOwnTheirAlgorithmsAloneAndFreeThem();
  void BadProjectIsRefusedWithDialog();
  void ProjectIntegrationFollowsTheSchema();
  void InsideViewFormFollowsThePictureSettings();
  void DistanceFieldAndConnectionFromPickedPoints();
  void PropertiesRefuseBadValues();
  void PythonTraceRebuildsPipeline();
  void CommandLineScreenshot();
  void CpuBackendSeesWhatTheGpuSees();
  void ExportsWriteWholeFiles();
  void FieldItemShowsCurvature();
  void DisplaysAreTheViewsKeyedByOutputType();
  void DraggingTheEyeMovesTheObserver();
  void SampledMetricReadsItsVolumeFromItsFolder();
  void MovingTheCameraTracesFewerRaysUntilItStops();
  void HoldingASliderTracesFewerRaysUntilItIsLetGo();
  void StillFramesComeInPiecesAndTheWindowAnswers();
  void WindowScreenshotWaitsForTheFinishedPicture();
  void TheWheelPreviewsThenRefines();
  void ProjectsTravelWithTheirFiles();
  void UnsavedChangesAreMarkedAndAsked();
  void RecentFilesAndShippedProjects();
  void HiddenItemsDoNotCompute();
  void HelpMenuListsShortcutsAndGuides();
  void UndoAndRedoEveryKindOfChange();
  void ColourMapEditorIsAppliedAndSaved();
  void SpreadsheetAndCsvExportShowThePoints();
  void TwoPointsOnThePickedRayMeasureItsArcLength();
  void AnimationFliesAlongACameraPathToFramesAndAFilm();
  void PythonShellRunsLinesAndScripts();
  void CancelledCpuRenderKeepsThePicture();
  void ColourRangeOverTimeSpansEveryT();
  void CameraPathKeysAreDraggedInTheOutsideView();
};

void TestStudio::WindowOpensWithDefaultScene()
{
  auto window = OpenWindow(true);
  QVERIFY(window);
  // The default session: the paper's grid, the Gaussian bump with sliders
  // for a and s, the observer at the default scene's camera.
  QCOMPARE(window->Document()->Scene()->HasDefinition(), false);
  QVERIFY(window->Browser()->SceneRow()->text(1).contains("default grid"));
  QVERIFY(window->Browser()->MetricRow()->text(1).contains("graph"));
  QVERIFY(window->Parameters()->Slider("/parameters/a"));
  QVERIFY(window->Parameters()->Slider("/parameters/s"));
  double position[3];
  window->Document()->Observer()->GetPosition(position);
  QCOMPARE(position[2], 7.5);
  // The inside view drew the grid (many colours, no error) with one shader.
  QCOMPARE(window->Inside()->LastError(), QString());
  QCOMPARE(window->Inside()->Pass()->GetNumberOfShaderCompilations(), 1);
  const QImage inside = window->Inside()->Capture();
  QVERIFY(DistinctColors(inside) > 50);
  QVERIFY(DistinctColors(window->Outside()->Capture()) > 50);
  // The outside view shows the observer's frustum: 4 edges + 4 rim lines.
  QCOMPARE(window->Outside()->Frustum()->GetNumberOfLines(), vtkIdType(8));
}

void TestStudio::SyntaxErrorShowsColumnAndKeepsPicture()
{
  auto window = OpenWindow();
  QVERIFY(window);
  const QImage before = window->Inside()->Capture();
  const std::string definition = window->Document()->MetricText();
  // Type a metric whose expression has an unknown symbol at column 5 of "f"
  // (line 3 of the text): as a user would, key by key.
  QPlainTextEdit* editor = window->Editor()->Editor();
  editor->selectAll();
  QTest::keyClick(editor, Qt::Key_Delete);
  const QStringList lines = { "{", " \"type\": \"graph\",", " \"f\": \"x + q*y\"", "}" };
  for (int i = 0; i < lines.size(); ++i)
  {
    QTest::keyClicks(editor, lines[i]);
    if (i + 1 < lines.size())
    {
      QTest::keyClick(editor, Qt::Key_Return);
    }
  }
  QTRY_VERIFY_WITH_TIMEOUT(!window->Editor()->ErrorText().isEmpty(), 5000);
  // "f" is on line 3; its string starts at column 8, so character 5 ("q") is column 12.
  QVERIFY2(window->Editor()->ErrorText().startsWith("Line 3, column 12: metric.f: column 5"),
    qPrintable(window->Editor()->ErrorText()));
  QVERIFY(editor->extraSelections().size() == 1);
  QCOMPARE(editor->extraSelections().first().cursor.selectedText(), QString("q"));
  // The last good metric is still the one in use, and the picture with it.
  QCOMPARE(window->Document()->MetricText(), definition);
  window->Inside()->RenderNow();
  QCOMPARE(DifferentPixels(before, window->Inside()->Capture()), 0.0);

  // A JSON syntax error (missing comma) is shown where the parser noticed
  // it: at the end of the unexpected "name".
  editor->setPlainText("{\n \"type\": \"euclidean\"\n \"name\": \"x\"\n}");
  window->Editor()->ApplyNow();
  QVERIFY2(window->Editor()->ErrorText().startsWith("Line 3, column 7: invalid JSON"),
    qPrintable(window->Editor()->ErrorText()));
  QCOMPARE(window->Document()->MetricText(), definition);

  // Fixing it applies it.
  editor->setPlainText("{\"type\": \"euclidean\"}");
  window->Editor()->ApplyNow();
  QCOMPARE(window->Editor()->ErrorText(), QString());
  QCOMPARE(window->Document()->Metric()->GetFamilyName(), std::string("euclidean"));
}

void TestStudio::SliderChangesViewWithoutRecompiling()
{
  auto window = OpenWindow();
  QVERIFY(window);
  vtkRiemannRayTracePass* pass = window->Inside()->Pass();
  const int compilations = pass->GetNumberOfShaderCompilations();
  const QImage before = window->Inside()->Capture();
  QSlider* slider = window->Parameters()->Slider("/parameters/a");
  QVERIFY(slider);
  // a from 1 to 0.3 (the slider spans [0, 2]): a flatter bump bends the rays less.
  slider->setValue(ParameterPanel::SliderSteps * 15 / 100);
  QCOMPARE(window->Document()->ParameterValue("/parameters/a"), 0.3);
  QVERIFY(window->Document()->EffectiveMetricText().find("\"a\": 0.3") != std::string::npos);
  const QImage after = window->Inside()->Capture();
  QVERIFY2(DifferentPixels(before, after) > 0.01, "the inside view did not change");
  QCOMPARE(pass->GetNumberOfShaderCompilations(), compilations);
  QVERIFY(window->LastUpdateMilliseconds() >= 0.0);
  // The slider and the spin box agree; the text in the editor is untouched.
  QCOMPARE(window->Parameters()->SpinBox("/parameters/a")->value(), 0.3);
  QVERIFY(window->Editor()->Text().contains("\"a\": 1.0"));

  // The time bar too: t is a uniform.
  window->Editor()->SetText(
    R"json({"type": "graph", "parameters": {"a": {"from": 0.2, "to": 1.5}, "s": 0.5},)json"
    R"json( "f": "a * exp(-(x^2 + y^2 + z^2) / (2 * s^2))"})json");
  window->Inside()->RenderNow();
  const int recompiled = pass->GetNumberOfShaderCompilations();
  const QImage atZero = window->Inside()->Capture();
  QVERIFY(!window->Parameters()->Slider("/parameters/a")); // animated: no slider
  QVERIFY(window->Parameters()->Slider("/parameters/s"));
  window->Document()->SetTime(1.0);
  QCOMPARE(pass->GetNumberOfShaderCompilations(), recompiled);
  QVERIFY(DifferentPixels(atZero, window->Inside()->Capture()) > 0.01);
}

void TestStudio::GeodesicItemAddsPolylines()
{
  auto window = OpenWindow();
  QVERIFY(window);
  // In Euclidean space geodesics are straight segments of the set length:
  // exact answers to check what the outside view is given.
  window->Editor()->SetText(R"({"type": "euclidean"})");
  const QImage before = window->Outside()->Capture();
  QAction* add = window->findChild<QAction*>("Add:geodesics");
  QVERIFY(add);
  add->trigger();
  QCOMPARE(int(window->Document()->Items().size()), 1);
  PipelineItem* item = window->Document()->Items().front().get();
  QVERIFY(window->Browser()->Row(item));
  QCOMPARE(window->Browser()->SelectedItem(), item);
  QVERIFY(WaitForJobs(*window));
  auto* lines = vtkPolyData::SafeDownCast(item->Result(0));
  QVERIFY(lines);
  const int directions = item->Settings().at("NumberOfDirections").get<int>();
  QCOMPARE(lines->GetNumberOfLines(), vtkIdType(directions));
  double seed[3];
  for (int i = 0; i < 3; ++i)
  {
    seed[i] = item->Settings().at("StartPosition")[i].get<double>();
  }
  const double length = item->Settings().at("MaximumPropagation").get<double>();
  vtkNew<vtkIdList> ids;
  lines->GetLines()->InitTraversal();
  while (lines->GetLines()->GetNextCell(ids))
  {
    double first[3], last[3], middle[3];
    lines->GetPoint(ids->GetId(0), first);
    lines->GetPoint(ids->GetId(ids->GetNumberOfIds() - 1), last);
    lines->GetPoint(ids->GetId(ids->GetNumberOfIds() / 2), middle);
    QVERIFY(std::sqrt(vtkMath::Distance2BetweenPoints(first, seed)) < 1e-12);
    QVERIFY(std::abs(std::sqrt(vtkMath::Distance2BetweenPoints(first, last)) - length) < 1e-9);
    // The midpoint lies on the chord (straight line).
    double a[3], b[3], cross[3];
    vtkMath::Subtract(middle, first, a);
    vtkMath::Subtract(last, first, b);
    vtkMath::Cross(a, b, cross);
    QVERIFY(vtkMath::Norm(cross) < 1e-9);
  }
  // The polylines are in the outside view, and they show.
  QVERIFY(ViewHasProp(window->Outside(), window->Outside()->DisplayOf(item)->Prop()));
  window->Outside()->RenderNow();
  QVERIFY(DifferentPixels(before, window->Outside()->Capture()) > 0.001);
  // Hide with a click on the eye, show again, rename in place, then delete.
  PipelineBrowser* browser = window->Browser();
  const QRect eye = browser->visualItemRect(browser->Row(item));
  QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, QPoint(10, eye.center().y()));
  QVERIFY(!item->IsVisible());
  QVERIFY(!window->Outside()->DisplayOf(item)->Prop()->GetVisibility());
  QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, QPoint(10, eye.center().y()));
  QVERIFY(item->IsVisible());
  browser->Row(item)->setText(1, "Straight lines");
  QCOMPARE(item->Name(), QString("Straight lines"));
  QTest::keyClick(browser, Qt::Key_Delete);
  QVERIFY(window->Document()->Items().empty());
  QVERIFY(!browser->Row(item));
}

void TestStudio::PickedPixelShowsBundleRay()
{
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  int width, height;
  inside->PixelSize(width, height);
  // Ctrl+click a point of the inside view, as a user does.
  const QPoint click(width / 3, height / 4);
  QTest::mouseClick(inside, Qt::LeftButton, Qt::ControlModifier, click);
  vtkPolyData* picked = window->PickedRay();
  QCOMPARE(picked->GetNumberOfCells(), vtkIdType(1));
  // VTK's pixel rows count from the bottom.
  const int column = click.x(), row = height - 1 - click.y();
  const int* index = nullptr;
  vtkDataArray* pixel = picked->GetCellData()->GetArray("PixelIndex");
  QVERIFY(pixel);
  (void)index;
  QCOMPARE(int(pixel->GetComponent(0, 0)), column);
  QCOMPARE(int(pixel->GetComponent(0, 1)), row);

  // The same ray, traced by the toolkit's bundle for that pixel with the
  // view's camera and settings.
  vtkNew<vtkRiemannRayBundle> bundle;
  bundle->SetMetric(window->Document()->Metric());
  bundle->SetScene(window->Document()->Scene());
  bundle->SetCamera(inside->Renderer()->GetActiveCamera());
  bundle->SetWidth(width);
  bundle->SetHeight(height);
  bundle->SetUseSceneSettings(window->Document()->UseSceneSettings());
  bundle->GetIntegrationSettings()->DeepCopy(window->Document()->RaySettings());
  bundle->SetPixelRegion(column, column, row, row);
  bundle->UsePixelRegionOn();
  bundle->Update();
  vtkPolyData* expected = bundle->GetOutput();
  QCOMPARE(picked->GetNumberOfPoints(), expected->GetNumberOfPoints());
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    picked->GetPoint(i, p);
    expected->GetPoint(i, q);
    QCOMPARE(vtkMath::Distance2BetweenPoints(p, q), 0.0);
  }
  // The outside view shows it; the status bar says where it ended and why.
  QCOMPARE(window->Outside()->PickedRay()->GetNumberOfPoints(), expected->GetNumberOfPoints());
  QVERIFY2(window->StatusText().contains(QString("Pixel (%1, %2)").arg(column).arg(row)),
    qPrintable(window->StatusText()));
  QVERIFY(window->StatusText().contains("after length"));
}

void TestStudio::ProjectRoundTrip()
{
  QTemporaryDir folder;
  QVERIFY(folder.isValid());
  const QString project = folder.filePath("session.json");
  QImage inside, outside;
  nlohmann::json items = nlohmann::json::array();
  {
    auto window = OpenWindow();
    QVERIFY(window);
    QVERIFY(window->OpenFile(WriteQuickScene(folder), false).isEmpty());
    QVERIFY(window->Document()->SetParameterValue("/parameters/a", 0.5).Ok());
    PipelineItem* geodesics = window->Document()->AddItem("geodesics");
    QVERIFY(geodesics->ApplySettings({ { "NumberOfDirections", 7 }, { "ConeAngle", 25.0 } }).isEmpty());
    geodesics->SetName("Fan");
    PipelineItem* bundle = window->Document()->AddItem("ray-bundle");
    bundle->SetVisible(false);
    window->Document()->Observer()->Azimuth(10.0);
    window->Document()->ObserverChanged();
    window->Settle();
    QVERIFY(window->SaveProject(project).isEmpty());
    inside = window->Inside()->Capture();
    outside = window->Outside()->Capture();
    for (const auto& item : window->Document()->Items())
    {
      items.push_back({ item->Kind(), item->Name().toStdString(), item->IsVisible(), item->Settings() });
    }
  }
  auto window = OpenWindow();
  QVERIFY(window);
  QCOMPARE(window->OpenFile(project, false), QString());
  window->Settle();
  nlohmann::json reopened = nlohmann::json::array();
  for (const auto& item : window->Document()->Items())
  {
    reopened.push_back({ item->Kind(), item->Name().toStdString(), item->IsVisible(), item->Settings() });
  }
  QCOMPARE(QString::fromStdString(reopened.dump()), QString::fromStdString(items.dump()));
  QCOMPARE(window->Browser()->Row(window->Document()->Items().front().get())->text(1), QString("Fan"));
  QCOMPARE(DifferentPixels(inside, window->Inside()->Capture()), 0.0);
  QVERIFY(DifferentPixels(outside, window->Outside()->Capture()) < 0.001);
}

void TestStudio::JobsOwnTheirAlgorithmsAloneAndFreeThem()
{
  JobRunner runner;
  vtkWeakPointer<ReferenceProbe> freed[2];
  ReferenceProbe* running[2] = { nullptr, nullptr };
  int finished = 0;
  for (int k = 0; k < 2; ++k)
  {
    {
      // The handle as the document holds it (a converted handle would be
      // emptied by the conversion, hiding a copy made by Start).
      vtkSmartPointer<vtkAlgorithm> probe = vtkSmartPointer<ReferenceProbe>::New();
      running[k] = static_cast<ReferenceProbe*>(probe.Get());
      freed[k] = running[k];
      runner.Start(&freed[k], std::move(probe), "probe",
        [&finished](vtkAlgorithm* job, bool ok, const QString& error) {
          auto* done = static_cast<ReferenceProbe*>(job);
          QVERIFY(ok && error.isEmpty());
          QVERIFY(done->Before > 0);
          QCOMPARE(done->After.load(), done->Before.load());
          ++finished;
        });
      QVERIFY(runner.IsRunning(&freed[k]));
      // The job has started and counted its references; the caller's handle
      // is still in scope.
      QVERIFY(QTest::qWaitFor([&]() { return running[k]->Entered.load(); }, 10000));
    }
    // The caller's scope is over: the job counts again (the second job
    // starts while the first waits).
    running[k]->GoOn = true;
  }
  runner.WaitForAll();
  QTRY_COMPARE(finished, 2);
  // A finished job is freed (its algorithm and output), on this thread,
  // once its callback has run: not kept for the runner's life.
  QTRY_VERIFY(!freed[0] && !freed[1]);
}

void TestStudio::CancelledJobLeavesAppResponsive()
{
  auto window = OpenWindow();
  QVERIFY(window);
  // A curvature field far too big to finish during the test (about 4
  // million points with third derivatives), after a small one that finished.
  PipelineItem* field = window->Document()->AddItem(MakePipelineItem("field", "Curvature"));
  QVERIFY(field->ApplySettings({ { "Dimensions", { 9, 9, 9 } } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  vtkDataObject* small = field->Result(0);
  QVERIFY(small);
  QCOMPARE(small->GetNumberOfElements(vtkDataObject::POINT), vtkIdType(9 * 9 * 9));
  QVERIFY(field->ApplySettings({ { "Dimensions", { 160, 160, 160 } } }).isEmpty());
  QTRY_VERIFY_WITH_TIMEOUT(window->CancelButton()->isVisible(), 5000);
  // The window answers while the job runs: timers fire on time.
  QElapsedTimer answered;
  answered.start();
  QTest::qWait(300);
  QVERIFY(answered.elapsed() < 1500);
  QTest::mouseClick(window->CancelButton(), Qt::LeftButton);
  QTRY_VERIFY_WITH_TIMEOUT(window->Document()->Jobs()->NumberOfRunningJobs() == 0, 20000);
  QVERIFY(!window->CancelButton()->isVisible());
  // Cancelled: the item keeps its last result, and no error is reported;
  // its settings are the ones that result was computed with (the view and
  // the properties agree).
  QCOMPARE(field->Result(0)->GetNumberOfElements(vtkDataObject::POINT), vtkIdType(9 * 9 * 9));
  QCOMPARE(window->Document()->ItemError(field), QString());
  QCOMPARE(QString::fromStdString(field->Settings().at("Dimensions").dump()), QString("[9,9,9]"));
  // Responsive: a slider move updates the inside view at once; the field
  // (which depends on the metric) runs again with those settings, not the
  // cancelled 160^3 (nothing cancelled restarts by itself).
  const QImage before = window->Inside()->Capture();
  window->Document()->SetParameterValue("/parameters/a", 0.2);
  QVERIFY(DifferentPixels(before, window->Inside()->Capture()) > 0.01);
  QVERIFY(WaitForJobs(*window, 20000));
  QCOMPARE(field->Result(0)->GetNumberOfElements(vtkDataObject::POINT), vtkIdType(9 * 9 * 9));
  window->Document()->RemoveItem(field);
  QVERIFY(WaitForJobs(*window, 20000));
}

void TestStudio::ProjectIntegrationFollowsTheSchema()
{
  // A project's inside.integration is vtkRiemannIntegrationSettings's
  // properties, read and checked through their declaration
  // (vtkRiemannIntegrationSettings.settings.json): its ranges, its words;
  // written back the same.
  const auto parse = [](const std::string& integration)
  {
    return riemann::studio::ParseProject(R"({"riemann-studio": 1,
 "metric": {"text": "{\"type\": \"euclidean\"}"},
 "observer": {"position": [0, 0, 5], "focal-point": [0, 0, 0], "view-up": [0, 1, 0], "view-angle": 30},
 "inside": {"integration": )" + integration + "}}");
  };
  const auto error = [&parse](const std::string& integration) -> std::string
  {
    try
    {
      parse(integration);
    }
    catch (const riemann::studio::ProjectError& e)
    {
      return e.what();
    }
    return "(accepted)";
  };
  QCOMPARE(error(R"({"InitialIntegrationStep": 0})"),
    std::string("inside.integration.InitialIntegrationStep: expected a number from 1e-09 to "
                "1e+06 (arc length), got 0"));
  QCOMPARE(error(R"({"MaximumNumberOfSteps": 2.5})"),
    std::string("inside.integration.MaximumNumberOfSteps: expected a whole number from 1 to "
                "1e+09 (steps), got 2.5"));
  QCOMPARE(error(R"({"IntegratorType": "rk5"})"),
    std::string("inside.integration.IntegratorType: expected one of euler, rk4, dp45, got \"rk5\""));
  QCOMPARE(error(R"({"Step": 0.1})"), std::string("inside.integration.Step: unknown setting"));

  // Every setting the app shows, round trip through the settings object.
  const riemann::studio::ProjectData project = parse(R"({"IntegratorType": "dp45",
    "InitialIntegrationStep": 0.05, "MaximumError": 1e-6, "MaximumPropagation": 12,
    "MaximumNumberOfSteps": 1234})");
  vtkNew<vtkRiemannIntegrationSettings> settings;
  riemann::studio::ApplyIntegrationValues(project.Integration, settings);
  QCOMPARE(settings->GetIntegratorType(), static_cast<int>(vtkRiemannIntegrationSettings::DORMAND_PRINCE45));
  QCOMPARE(settings->GetInitialIntegrationStep(), 0.05);
  QCOMPARE(settings->GetMaximumError(), 1e-6);
  QCOMPARE(settings->GetMaximumPropagation(), 12.0);
  QCOMPARE(settings->GetMaximumNumberOfSteps(), static_cast<vtkIdType>(1234));
  const nlohmann::json values = riemann::studio::IntegrationValues(settings);
  for (auto entry = project.Integration.begin(); entry != project.Integration.end(); ++entry)
  {
    QCOMPARE(values.at(entry.key()), entry.value());
  }
  // Every declared setting is stored, the ones the project did not give at their defaults.
  QCOMPARE(values.size(), riemann::declared::vtkRiemannIntegrationSettings::Settings.Count);
}

void TestStudio::InsideViewFormFollowsThePictureSettings()
{
  // The inside view's form: the observer's camera, samples and renderer as
  // vtkRiemannPictureSettings declares them, its ranges and the refusal of
  // a camera that defines no view; a project's observer and inside objects
  // in the declared names (an older project's keys still read) and words.
  auto window = OpenWindow();
  QVERIFY(window);
  window->Browser()->SelectScene();
  PropertiesPanel* panel = window->Properties();
  for (const char* key : { "Position", "LookAt", "ViewUp", "ViewAngle", "SamplesPerPixel", "Backend" })
  {
    QVERIFY2(panel->Field(key), key);
  }
  vtkCamera* observer = window->Document()->Observer();
  auto* angle = qobject_cast<QLineEdit*>(panel->Field("ViewAngle"));
  QVERIFY(angle);
  angle->selectAll();
  QTest::keyClicks(angle, "179.5");
  QVERIFY2(panel->FieldError("ViewAngle").contains("179"), qPrintable(panel->FieldError("ViewAngle")));
  QVERIFY(!panel->Apply());
  angle->selectAll();
  QTest::keyClicks(angle, "45");
  QVERIFY(panel->Apply());
  QCOMPARE(observer->GetViewAngle(), 45.0);
  // Looking at the point it stands on: refused whole, the camera kept.
  const double* eye = observer->GetPosition();
  const double position[3] = { eye[0], eye[1], eye[2] };
  const double focal[3] = { observer->GetFocalPoint()[0], observer->GetFocalPoint()[1],
    observer->GetFocalPoint()[2] };
  for (int i = 0; i < 3; ++i)
  {
    auto* lookAt = qobject_cast<QLineEdit*>(panel->Field("LookAt", i));
    QVERIFY(lookAt);
    lookAt->selectAll();
    QTest::keyClicks(lookAt, QString::number(position[i]));
    QVERIFY2(panel->FieldError("LookAt").isEmpty(), qPrintable(panel->FieldError("LookAt")));
  }
  angle->selectAll();
  QTest::keyClicks(angle, "30");
  QVERIFY(!panel->Apply());
  const QString status = panel->findChild<QLabel*>("PropertiesStatus")->text();
  QVERIFY2(status.contains("the camera is at the point it looks at"), qPrintable(status));
  QCOMPARE(observer->GetViewAngle(), 45.0);
  for (int i = 0; i < 3; ++i)
  {
    QCOMPARE(observer->GetFocalPoint()[i], focal[i]);
  }
  auto* samples = qobject_cast<QLineEdit*>(panel->Field("SamplesPerPixel"));
  QVERIFY(samples);
  samples->selectAll();
  QTest::keyClicks(samples, "4097");
  QVERIFY(!panel->FieldError("SamplesPerPixel").isEmpty());

  const auto error = [](const std::string& observer, const std::string& inside) -> std::string
  {
    try
    {
      riemann::studio::ParseProject(R"({"riemann-studio": 1,
 "metric": {"text": "{\"type\": \"euclidean\"}"}, "observer": )" + observer +
        R"(, "inside": )" + inside + "}");
    }
    catch (const riemann::studio::ProjectError& e)
    {
      return e.what();
    }
    return "(accepted)";
  };
  const std::string fine =
    R"({"position": [0, 0, 5], "focal-point": [0, 0, 0], "view-up": [0, 1, 0], "view-angle": 30})";
  QCOMPARE(error(fine, "{}"), std::string("(accepted)"));
  QCOMPARE(error(R"({"position": [0, 0, 5], "focal-point": [0, 0, 0], "view-up": [0, 1, 0], "view-angle": 180})", "{}"),
    std::string("observer.view-angle is 180: expected a number above 0 and at most 179 (degrees)"));
  QCOMPARE(error(R"({"Position": [0, 0, 5], "LookAt": [0, 0, 0], "ViewUp": [0, 0, 0], "ViewAngle": 30})", "{}"),
    std::string("observer.ViewUp is the zero vector: a direction must not be zero"));
  QCOMPARE(error(R"({"position": [0, 0, 5], "focal-point": [0, 0, 0], "view-up": [0, 0, 3], "view-angle": 30})", "{}"),
    std::string("observer: the view up is along the view direction"));
  QCOMPARE(error(R"({"Position": [0, 0, 5], "LookAt": [0, 0, 5]})", "{}"),
    std::string("observer: the camera is at the point it looks at"));
  QCOMPARE(error(fine, R"({"samples": 5000})"),
    std::string("inside.samples is 5000: expected a whole number from 1 to 4096"));
  QCOMPARE(error(fine, R"({"Backend": "vulkan"})"),
    std::string("inside.Backend: expected one of gpu, cpu"));
  // A project keeps the declared names; an old one's keys read the same.
  riemann::studio::ProjectData project = riemann::studio::ParseProject(R"({"riemann-studio": 1,
 "metric": {"text": "{\"type\": \"euclidean\"}"}, "observer": )" + fine + R"(, "inside": {"samples": 4}})");
  QCOMPARE(project.Observer.Values.at("LookAt"), nlohmann::json({ 0.0, 0.0, 0.0 }));
  QCOMPARE(project.Observer.Values.at("ViewAngle").get<double>(), 30.0);
  QCOMPARE(project.Samples, 4);
  const nlohmann::json written = riemann::studio::ProjectToJson(project);
  QCOMPARE(written.at("observer").at("ViewAngle").get<double>(), 30.0);
  QVERIFY(!written.at("observer").contains("view-angle"));
  QCOMPARE(written.at("inside").at("SamplesPerPixel").get<int>(), 4);
}

void TestStudio::BadProjectIsRefusedWithDialog()
{
  auto window = OpenWindow();
  QVERIFY(window);
  QTemporaryDir folder;
  const QString path = folder.filePath("bad.json");
  QFile file(path);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write(R"({"riemann-studio": 1,
 "metric": {"text": "{\"type\": \"euclidean\"}"},
 "observer": {"position": [0, 0, 5], "focal-point": [0, 0, 0], "view-up": [0, 1, 0], "view-angle": 30},
 "items": [{"kind": "geodesics", "settings": {"ConeAngle": 500}}]})");
  file.close();
  const std::string metric = window->Document()->MetricText();
  QString dialogText;
  QTimer::singleShot(200, [&dialogText]() {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (box)
    {
      dialogText = box->text();
      box->accept();
    }
  });
  const QString error = window->OpenFile(path, true);
  QVERIFY2(dialogText.contains("items[0].settings: Cone angle: must be in [0, 180]"),
    qPrintable(dialogText));
  QVERIFY(dialogText.contains("Nothing was changed"));
  QVERIFY(error.contains("bad.json"));
  // Nothing changed, and the app goes on.
  QCOMPARE(window->Document()->MetricText(), metric);
  QVERIFY(window->Document()->Items().empty());
  // Malformed JSON: the place is named.
  QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
  file.write("{\"riemann-studio\": 1,\n \"metric\": }");
  file.close();
  const QString syntax = window->OpenFile(path, false);
  QVERIFY2(syntax.contains("line 2, column"), qPrintable(syntax));
  QCOMPARE(window->Document()->MetricText(), metric);
}

void TestStudio::PropertiesRefuseBadValues()
{
  auto window = OpenWindow();
  QVERIFY(window);
  PipelineItem* item = window->Document()->AddItem("exponential-map");
  window->Browser()->Select(item);
  PropertiesPanel* panel = window->Properties();
  auto* angle = qobject_cast<QLineEdit*>(panel->Field("ConeAngle"));
  QVERIFY(angle);
  angle->selectAll();
  QTest::keyClicks(angle, "200");
  QVERIFY2(panel->FieldError("ConeAngle").contains("must be in [0, 180]"),
    qPrintable(panel->FieldError("ConeAngle")));
  QVERIFY(!panel->findChild<QPushButton*>("ApplyButton")->isEnabled());
  QVERIFY(!panel->Apply());
  // The declared default (vtkRiemannExponentialMap.settings.json), as the filter has it.
  QCOMPARE(item->Settings().at("ConeAngle").get<double>(), 180.0);
  auto* step = qobject_cast<QLineEdit*>(panel->Field("InitialIntegrationStep"));
  step->selectAll();
  QTest::keyClicks(step, "abc");
  QVERIFY(panel->FieldError("InitialIntegrationStep").contains("not a number"));
  // The radii of the wavefronts: a list, every one positive.
  auto* radii = qobject_cast<QLineEdit*>(panel->Field("Radii"));
  QVERIFY(radii);
  QCOMPARE(radii->text(), QString()); // none by default, as the filter
  radii->selectAll();
  QTest::keyClicks(radii, "1, -2");
  QVERIFY2(panel->FieldError("Radii").contains("number 2: must be in (0, 1e+09]"),
    qPrintable(panel->FieldError("Radii")));
  radii->selectAll();
  QTest::keyClicks(radii, "1, 2.5");
  QVERIFY(panel->FieldError("Radii").isEmpty());
  // Good values apply.
  angle->selectAll();
  QTest::keyClicks(angle, "20");
  step->selectAll();
  QTest::keyClicks(step, "0.02");
  QVERIFY(panel->FieldError("ConeAngle").isEmpty());
  QVERIFY(panel->Apply());
  QCOMPARE(item->Settings().at("ConeAngle").get<double>(), 20.0);
  QCOMPARE(item->Settings().at("InitialIntegrationStep").get<double>(), 0.02);
  QCOMPARE(QString::fromStdString(item->Settings().at("Radii").dump()), QString("[1.0,2.5]"));
  window->Document()->Jobs()->CancelAll();
  QVERIFY(WaitForJobs(*window));
}

void TestStudio::PythonTraceRebuildsPipeline()
{
  auto window = OpenWindow();
  QVERIFY(window);
  PipelineItem* geodesics = window->Document()->AddItem("geodesics");
  QVERIFY(geodesics->ApplySettings({ { "NumberOfDirections", 5 } }).isEmpty());
  PipelineItem* bundle = window->Document()->AddItem("ray-bundle");
  QVERIFY(bundle->ApplySettings({ { "SubgridResolution", 3 } }).isEmpty());
  window->Document()->SetParameterValue("/parameters/a", 0.7);
  QVERIFY(WaitForJobs(*window));
  QTemporaryDir folder;
  QString output;
  QVERIFY2(RunExportedScript(*window, folder, output), qPrintable(output));
  // The script's filters give the app's results, point for point.
  for (const auto& item : window->Document()->Items())
  {
    const vtkIdType points = vtkPolyData::SafeDownCast(item->Result(0))->GetNumberOfPoints();
    QVERIFY2(output.contains(QString("%1: vtkPolyData with %2 points").arg(item->Name()).arg(points)),
      qPrintable(output));
    QVERIFY(QFileInfo::exists(folder.filePath("out/" + item->Name() + ".vtp")));
  }
}

void TestStudio::CommandLineScreenshot()
{
  const QString binary = QString::fromLocal8Bit(qgetenv("RIEMANN_BIN_DIR")) + "/riemann-studio";
  if (!QFileInfo::exists(binary))
  {
    QSKIP("RIEMANN_BIN_DIR/riemann-studio not found (run through ctest)");
  }
  QTemporaryDir folder;
  const QString shot = folder.filePath("shot.png");
  QProcess app;
  app.start(binary, { WriteQuickScene(folder), "--screenshot", shot, "--view", "both",
                      "--size", "900x500" });
  QVERIFY(app.waitForFinished(180000));
  QVERIFY2(app.exitCode() == 0, app.readAllStandardError().constData());
  const QImage image(shot);
  QVERIFY(!image.isNull());
  QVERIFY(DistinctColors(image) > 50);
  // --size is the picture's: both views side by side, 900 x 500 in all.
  QCOMPARE(image.size(), QSize(900, 500));
  // One view, larger than the screen (Xvfb's 1280 x 1024): whole.
  const QString large = folder.filePath("large.png");
  app.start(binary, { WriteQuickScene(folder), "--screenshot", large, "--view", "inside",
                      "--size", "1400x1100" });
  QVERIFY(app.waitForFinished(300000));
  QVERIFY2(app.exitCode() == 0, app.readAllStandardError().constData());
  QCOMPARE(QImage(large).size(), QSize(1400, 1100));
  // A bad file: exit status 1 and a message naming the file; no picture.
  QFile bad(folder.filePath("bad-metric.json"));
  QVERIFY(bad.open(QIODevice::WriteOnly));
  bad.write("{\"type\": \"graph\", \"f\": \"x +\"}");
  bad.close();
  const QString none = folder.filePath("none.png");
  app.start(binary, { bad.fileName(), "--screenshot", none });
  QVERIFY(app.waitForFinished(120000));
  QCOMPARE(app.exitCode(), 1);
  const QString message = QString::fromUtf8(app.readAllStandardError());
  QVERIFY2(message.contains("bad-metric.json") && message.contains("metric.f: column"),
    qPrintable(message));
  QVERIFY(!QFileInfo::exists(none));
  // Bad options: exit status 2.
  app.start(binary, { "--screenshot", none, "--view", "sideways" });
  QVERIFY(app.waitForFinished(60000));
  QCOMPARE(app.exitCode(), 2);
  // A pixel outside the inside view is refused, not silently skipped.
  app.start(binary, { WriteQuickScene(folder), "--screenshot", none, "--pick", "5000,5000",
                      "--size", "640x400" });
  QVERIFY(app.waitForFinished(180000));
  QCOMPARE(app.exitCode(), 2);
  QVERIFY(QString::fromUtf8(app.readAllStandardError()).contains("--pick 5000,5000: outside the inside view"));
  QVERIFY(!QFileInfo::exists(none));
  // No display: a message that says what to do, exit status 1 (not Qt's abort).
  QProcessEnvironment headless = QProcessEnvironment::systemEnvironment();
  headless.remove("DISPLAY");
  headless.remove("WAYLAND_DISPLAY");
  headless.remove("QT_QPA_PLATFORM");
  app.setProcessEnvironment(headless);
  app.start(binary, { WriteQuickScene(folder), "--screenshot", none });
  QVERIFY(app.waitForFinished(60000));
  QCOMPARE(app.exitStatus(), QProcess::NormalExit);
  QCOMPARE(app.exitCode(), 1);
  QVERIFY(QString::fromUtf8(app.readAllStandardError()).contains("no display"));
}

void TestStudio::CpuBackendSeesWhatTheGpuSees()
{
  auto window = OpenWindow();
  QVERIFY(window);
  QTemporaryDir folder;
  QVERIFY(window->OpenFile(WriteQuickScene(folder), false).isEmpty());
  window->Settle();
  const QImage gpu = window->Inside()->Capture();
  // Switch the renderer in the inside view's properties (select the scene).
  window->Browser()->SelectScene();
  PropertiesPanel* panel = window->Properties();
  QVERIFY(panel->Field("Backend"));
  QVERIFY(panel->Field("SamplesPerPixel"));
  window->Inside()->SetBackend(InsideView::CPU);
  window->Settle();
  QCOMPARE(window->Inside()->GetBackend(), InsideView::CPU);
  const QImage cpu = window->Inside()->Capture();
  QCOMPARE(cpu.size(), gpu.size());
  // Same rays (float on the GPU, double on the CPU): the pictures agree but
  // for pixels at silhouettes and checker edges.
  int far = 0;
  for (int row = 0; row < gpu.height(); ++row)
  {
    for (int column = 0; column < gpu.width(); ++column)
    {
      const QColor a = gpu.pixelColor(column, row), b = cpu.pixelColor(column, row);
      far += std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
          std::abs(a.blue() - b.blue()) > 60;
    }
  }
  QVERIFY2(far < gpu.width() * gpu.height() / 20, qPrintable(QString("%1 pixels differ").arg(far)));
  QVERIFY(DistinctColors(cpu) > 5); // not a cleared view
}

void TestStudio::ExportsWriteWholeFiles()
{
  auto window = OpenWindow();
  QVERIFY(window);
  QTemporaryDir folder;
  // Frames of an animated metric: t = 0, 0.5, 1, each a PNG, all different.
  window->Editor()->SetText(
    R"json({"type": "graph", "parameters": {"a": {"from": 0, "to": 1.5}},)json"
    R"json( "f": "a * exp(-(x^2 + y^2 + z^2) / 0.5)"})json");
  AnimationSettings animation;
  animation.Frames = 3;
  animation.Width = 160;
  animation.Height = 120;
  animation.Output = folder.filePath("frame.png");
  QCOMPARE(ExportAnimation(*window, animation), QString());
  QImage frames[3];
  for (int k = 0; k < 3; ++k)
  {
    frames[k] = QImage(folder.filePath(QString::asprintf("frame_%04d.png", k)));
    QVERIFY(!frames[k].isNull());
    QCOMPARE(frames[k].size(), QSize(160, 120));
  }
  QVERIFY(DifferentPixels(frames[0], frames[2]) > 0.01);
  QCOMPARE(window->Document()->Time(), 0.0); // back where it was
  // An item's data, readable by VTK (as ParaView reads it).
  PipelineItem* geodesics = window->Document()->AddItem("geodesics");
  QVERIFY(WaitForJobs(*window));
  const QString vtp = folder.filePath("geodesics.vtp");
  QCOMPARE(window->ExportItemData(geodesics, vtp), QString());
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(vtp.toLocal8Bit().constData());
  reader->Update();
  QCOMPARE(reader->GetOutput()->GetNumberOfPoints(),
    vtkPolyData::SafeDownCast(geodesics->Result(0))->GetNumberOfPoints());
  QVERIFY(reader->GetOutput()->GetPointData()->GetArray("ArcLength"));
  // A place that cannot be written: an error, and no file.
  const QString error = window->ExportItemData(geodesics, "/proc/no-such-folder/x.vtp");
  QVERIFY2(error.contains("/proc/no-such-folder/x.vtp"), qPrintable(error));
  QVERIFY(!QFileInfo::exists("/proc/no-such-folder/x.vtp"));
  QVERIFY(!window->SaveProject("/proc/no-such-folder/p.json").isEmpty());
  // Both views side by side.
  const QString both = folder.filePath("both.png");
  QCOMPARE(window->SaveScreenshot(both, StudioMainWindow::BothShot), QString());
  const QImage shot(both);
  QCOMPARE(shot.width(), window->Inside()->Capture().width() + window->Outside()->Capture().width());
}

void TestStudio::DistanceFieldAndConnectionFromPickedPoints()
{
  // "Add Distance Field" and "Connect Two Points" on the round 3-sphere:
  // Ctrl+click in the outside view places the distance field's seed and the
  // connection's ends; the connection finds both arcs of the great circle
  // (lengths d and 2 pi - d), the field's distance at the far point is d.
  auto window = OpenWindow();
  QVERIFY(window);
  QFile metric(DataFile("metrics/round-sphere.json"));
  QVERIFY(metric.open(QIODevice::ReadOnly));
  QCOMPARE(window->Editor()->SetText(QString::fromUtf8(metric.readAll())), QString());
  QVERIFY(window->findChild<QAction*>("Add:distance-field"));
  QCOMPARE(window->findChild<QAction*>("Add:connect")->text(), QString("Connect Two Points"));

  PipelineItem* field = window->Document()->AddItem("distance-field");
  QVERIFY(field->ApplySettings({ { "Dimensions", { 21, 21, 21 } } }).isEmpty());
  window->Browser()->Select(field);
  window->PlacePoint(0.4, 0.1, -0.2);
  QCOMPARE(QString::fromStdString(field->Settings().at("Seed").dump()), QString("[0.4,0.1,-0.2]"));
  PipelineItem* connection = window->Document()->AddItem("connect");
  window->Browser()->Select(connection);
  // From (by a real pick in the outside view: a point on the plane through
  // its focal point, if nothing is drawn there), then To.
  const std::string before = connection->Settings().at("StartPosition").dump();
  window->Outside()->PickPoint(window->Outside()->width() / 2, window->Outside()->height() / 2);
  QVERIFY(connection->Settings().at("StartPosition").dump() != before);
  window->PlacePoint(0.0, 0.0, 0.0); // To
  window->PlacePoint(0.4, 0.1, -0.2); // From again
  window->PlacePoint(-0.3, 0.5, 0.6); // To again
  QCOMPARE(QString::fromStdString(connection->Settings().at("StartPosition").dump()),
    QString("[0.4,0.1,-0.2]"));
  QCOMPARE(QString::fromStdString(connection->Settings().at("EndPosition").dump()),
    QString("[-0.3,0.5,0.6]"));
  QVERIFY(connection->ApplySettings({ { "MaximumPropagation", 7.0 }, { "NumberOfDirections", 500 } })
            .isEmpty());
  QVERIFY(WaitForJobs(*window, 120000));
  // The two arcs.
  const auto sphere = [](double x, double y, double z) {
    const double r2 = x * x + y * y + z * z;
    return std::array<double, 4>{ 2 * x / (1 + r2), 2 * y / (1 + r2), 2 * z / (1 + r2),
      (1 - r2) / (1 + r2) };
  };
  const auto p = sphere(0.4, 0.1, -0.2), q = sphere(-0.3, 0.5, 0.6);
  const double d = std::acos(p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3]);
  auto* arcs = vtkPolyData::SafeDownCast(connection->Result(0));
  QVERIFY(arcs);
  QCOMPARE(arcs->GetNumberOfLines(), vtkIdType(2));
  vtkDataArray* length = arcs->GetCellData()->GetArray("Length");
  QVERIFY(std::abs(length->GetTuple1(0) - d) < 1e-8);
  QVERIFY(std::abs(length->GetTuple1(1) - (2 * 3.14159265358979323846 - d)) < 1e-8);
  // The field, at the grid point nearest q: the distance d within its error.
  auto* image = vtkImageData::SafeDownCast(field->Result(0));
  QVERIFY(image && image->GetPointData()->GetArray("Distance"));
  const double at[3] = { -0.4, 0.4, 0.6 }; // a grid point of the default bounds (spacing 0.2)
  const vtkIdType n = image->FindPoint(at[0], at[1], at[2]);
  const auto a = sphere(at[0], at[1], at[2]);
  const double exact = std::acos(p[0] * a[0] + p[1] * a[1] + p[2] * a[2] + p[3] * a[3]);
  const double u = image->GetPointData()->GetArray("Distance")->GetTuple1(n);
  // First order on this coarse grid (h = 0.2): within h / 2 (measured 0.07).
  QVERIFY2(std::abs(u - exact) < 0.1, qPrintable(QString("%1 vs %2").arg(u).arg(exact)));
  // The exported script rebuilds both.
  QTemporaryDir folder;
  QString output;
  QVERIFY2(RunExportedScript(*window, folder, output), qPrintable(output));
  QVERIFY2(output.contains(QString("%1: vtkPolyData with %2 points")
                             .arg(connection->Name())
                             .arg(arcs->GetNumberOfPoints())),
    qPrintable(output));
}

void TestStudio::FieldItemShowsCurvature()
{
  auto window = OpenWindow();
  QVERIFY(window);
  // The round 3-sphere: sectional curvature 1, so scalar curvature 6 everywhere.
  QString text;
  QFile metric(DataFile("metrics/round-sphere.json"));
  QVERIFY(metric.open(QIODevice::ReadOnly));
  QCOMPARE(window->Editor()->SetText(QString::fromUtf8(metric.readAll())), QString());
  PipelineItem* field = window->Document()->AddItem("field");
  QVERIFY(field->ApplySettings({ { "Dimensions", { 9, 9, 9 } } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  auto* image = vtkImageData::SafeDownCast(field->Result(0));
  QVERIFY(image);
  vtkDataArray* scalar = image->GetPointData()->GetArray("ScalarCurvature");
  QVERIFY(scalar);
  for (vtkIdType i = 0; i < scalar->GetNumberOfTuples(); ++i)
  {
    QVERIFY2(std::abs(scalar->GetTuple1(i) - 6.0) < 1e-6, qPrintable(QString::number(scalar->GetTuple1(i))));
  }
  // What the outside view draws: the slice through the centre, coloured by it.
  auto shown = [&window, field]() {
    vtkProp3DCollection* parts = window->Outside()->DisplayOf(field)->Prop()->GetParts();
    parts->InitTraversal();
    auto* actor = vtkActor::SafeDownCast(parts->GetNextProp3D());
    return vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
  };
  QVERIFY(shown()->GetNumberOfPolys() > 0);
  double bounds[6];
  shown()->GetBounds(bounds);
  QCOMPARE(bounds[4], 0.0); // the z = 0 slice
  QCOMPARE(bounds[5], 0.0);
  // Glyphs of the metric tensor: g = n^2 I, so every glyph is a sphere.
  QVERIFY(field->ApplySettings({ { "Field", "metric-tensor" }, { "Representation", "glyphs" },
                                 { "ColorArray", "Solid" } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  QVERIFY(shown()->GetNumberOfPoints() > 100);
  // An isosurface of the volume form sqrt(det g) = n^3 = 1: the sphere r = 1.
  QVERIFY(field->ApplySettings({ { "Field", "volume-form" }, { "Representation", "isosurface" },
                                 { "ContourValue", 1.0 }, { "ColorArray", "VolumeForm" } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  vtkPolyData* surface = shown();
  QVERIFY(surface->GetNumberOfPoints() > 50);
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); i += 7)
  {
    double p[3];
    surface->GetPoint(i, p);
    QVERIFY2(std::abs(vtkMath::Norm(p) - 1.0) < 0.05, qPrintable(QString::number(vtkMath::Norm(p))));
  }
}

void TestStudio::DisplaysAreTheViewsKeyedByOutputType()
{
  // Every item says what it shows by data type; a display exists for each,
  // and the item's form and settings carry that display's declared settings.
  vtkNew<vtkAssembly> parts;
  for (const std::string& kind : PipelineItemKinds())
  {
    std::unique_ptr<PipelineItem> item = MakePipelineItem(kind, "item");
    QVERIFY(item);
    QVERIFY2(!item->Looks().empty(), kind.c_str());
    std::vector<std::string> types;
    for (const OutputLook& look : item->Looks())
    {
      QVERIFY2(MakeOutputDisplay(look.DataType, parts) != nullptr, (kind + ": " + look.DataType).c_str());
      types.push_back(look.DataType);
    }
    std::vector<std::string> keys;
    for (const PropertySpec& spec : item->Properties())
    {
      keys.push_back(spec.Key);
    }
    for (const PropertySpec& spec : DisplayPropertySpecs(types, QStringList(), "Solid"))
    {
      QVERIFY2(std::count(keys.begin(), keys.end(), spec.Key) == 1, (kind + ": " + spec.Key).c_str());
      QVERIFY2(spec.Display && !spec.Default.is_null(), spec.Key.c_str());
      QVERIFY2(item->Settings().contains(spec.Key), (kind + ": " + spec.Key).c_str());
    }
    QVERIFY(MakeOutputDisplay("vtkUnstructuredGrid", parts) == nullptr);
  }
  // One display for every grid: a field and a distance field take the same
  // settings with the same declared defaults, but what an item overrides.
  auto field = MakePipelineItem("field", "field");
  auto distance = MakePipelineItem("distance-field", "distance");
  QCOMPARE(field->Settings().at("SliceNormal"), nlohmann::json("z"));
  QCOMPARE(distance->Settings().at("SliceNormal"), nlohmann::json("z"));
  QCOMPARE(field->Settings().at("NumberOfContours"), nlohmann::json(0));
  QCOMPARE(distance->Settings().at("NumberOfContours"), nlohmann::json(20));
  // The old key of a distance field's wavefronts still works (projects before displays).
  QCOMPARE(distance->ApplySettings({ { "NumberOfWavefronts", 7 } }), QString());
  QCOMPARE(distance->Settings().at("NumberOfContours"), nlohmann::json(7));
  QVERIFY(!distance->Settings().contains("NumberOfWavefronts"));

  // In the window: level lines of the curvature on a field's slice (a
  // distance field's wavefronts before), drawn by the grid's display.
  auto window = OpenWindow();
  QVERIFY(window);
  QFile metric(DataFile("metrics/round-sphere.json"));
  QVERIFY(metric.open(QIODevice::ReadOnly));
  QCOMPARE(window->Editor()->SetText(QString::fromUtf8(metric.readAll())), QString());
  PipelineItem* shown = window->Document()->AddItem("distance-field");
  QVERIFY(shown->ApplySettings({ { "Dimensions", { 17, 17, 5 } }, { "NumberOfContours", 5 } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  ItemDisplay* display = window->Outside()->DisplayOf(shown);
  QVERIFY(display);
  // The grid's surface and level lines, then the cut locus and the seed (one actor each).
  vtkProp3DCollection* actors = display->Prop()->GetParts();
  QCOMPARE(actors->GetNumberOfItems(), 2 + 2 + 2);
  actors->InitTraversal();
  auto* slice = vtkActor::SafeDownCast(actors->GetNextProp3D());
  auto* levels = vtkActor::SafeDownCast(actors->GetNextProp3D());
  QVERIFY(slice->GetVisibility() && levels->GetVisibility());
  auto* lines = vtkPolyData::SafeDownCast(levels->GetMapper()->GetInput());
  QVERIFY(lines && lines->GetNumberOfLines() > 0);
  // Each level line is a level set of the distance: its points have one of
  // the five values, evenly inside the grid's range.
  auto* image = vtkImageData::SafeDownCast(shown->Result(0));
  double range[2];
  image->GetPointData()->GetArray("Distance")->GetRange(range);
  QVERIFY(range[1] > range[0]);
  const double gap = (range[1] - range[0]) / 6;
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(lines);
  // The slice as drawn: the lines are its level sets (linear on its triangles).
  probe->SetSourceData(vtkPolyData::SafeDownCast(slice->GetMapper()->GetInput()));
  probe->Update();
  vtkDataArray* distances = vtkDataSet::SafeDownCast(probe->GetOutput())->GetPointData()->GetArray("Distance");
  QVERIFY(distances);
  for (vtkIdType i = 0; i < distances->GetNumberOfTuples(); ++i)
  {
    const double u = distances->GetTuple1(i);
    double nearest = 1e300;
    for (int k = 1; k <= 5; ++k)
    {
      nearest = std::min(nearest, std::abs(u - (range[0] + k * gap)));
    }
    QVERIFY2(nearest < 1e-6 * gap, qPrintable(QString("%1 (levels %2 apart)").arg(u).arg(gap)));
  }
  QCOMPARE(shown->ApplySettings({ { "NumberOfContours", 0 } }), QString());
  QVERIFY(!levels->GetVisibility());
  // Hidden item, hidden actors: the display follows the item's visibility.
  shown->SetVisible(false);
  QVERIFY(!display->Prop()->GetVisibility());
}

void TestStudio::DraggingTheEyeMovesTheObserver()
{
  auto window = OpenWindow();
  QVERIFY(window);
  OutsideView* outside = window->Outside();
  vtkCamera* observer = window->Document()->Observer();
  double eye[3], focal[3];
  observer->GetPosition(eye);
  observer->GetFocalPoint(focal);
  // Where the eye is on screen (VTK display coordinates, origin bottom left).
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToWorld();
  coordinate->SetValue(eye);
  const double* display = coordinate->GetComputedDoubleDisplayValue(outside->Renderer());
  const int height = outside->height();
  const QPoint start(int(display[0]), height - 1 - int(display[1]));
  const QPoint end = start + QPoint(40, 25);
  // A real drag: press, move with the button held, release.
  auto send = [outside](QEvent::Type type, QPoint at, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, outside->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(outside, &event);
  };
  send(QEvent::MouseMove, start, Qt::NoButton);
  send(QEvent::MouseButtonPress, start, Qt::LeftButton);
  for (int k = 1; k <= 5; ++k)
  {
    send(QEvent::MouseMove, start + (end - start) * k / 5, Qt::LeftButton);
  }
  send(QEvent::MouseButtonRelease, end, Qt::NoButton);
  double moved[3], movedFocal[3];
  observer->GetPosition(moved);
  observer->GetFocalPoint(movedFocal);
  QVERIFY2(std::sqrt(vtkMath::Distance2BetweenPoints(eye, moved)) > 0.05, "the observer did not move");
  // Eye and look-at point moved together: same view direction.
  for (int i = 0; i < 3; ++i)
  {
    QVERIFY(std::abs((movedFocal[i] - moved[i]) - (focal[i] - eye[i])) < 1e-9);
  }
  // The frustum drawn outside starts at the new eye.
  double apex[3];
  outside->Frustum()->GetPoint(0, apex);
  // (vtkPoints hold floats.)
  QVERIFY2(vtkMath::Distance2BetweenPoints(apex, moved) < 1e-10,
    qPrintable(QString("apex %1 %2 %3, eye %4 %5 %6").arg(apex[0]).arg(apex[1]).arg(apex[2])
      .arg(moved[0]).arg(moved[1]).arg(moved[2])));
}

int main(int argc, char* argv[])
{
  // The recent files (QSettings) of this run only, not the user's.
  QTemporaryDir settings;
  qputenv("XDG_CONFIG_HOME", settings.path().toLocal8Bit());
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestStudio test;
  return QTest::qExec(&test, argc, argv);
}

void TestStudio::SampledMetricReadsItsVolumeFromItsFolder()
{
  // The shipped phantom's metric names its volume relatively ("file":
  // "fibre-phantom.vti"); the app runs in another folder. The metric file,
  // the Python trace and a project saved elsewhere all find the volume.
  const QString metricFile = QString(RIEMANN_TEST_DATA_DIR) + "/phantom/fibre-phantom.json";
  const QString metricFolder = QFileInfo(metricFile).absolutePath();
  QVERIFY(QDir::currentPath() != metricFolder);
  QTemporaryDir folder;
  const QString project = folder.filePath("phantom-session.json");
  {
    auto window = OpenWindow();
    QVERIFY(window);
    QCOMPARE(window->OpenFile(metricFile, false), QString());
    window->Settle();
    vtkRiemannMetric* metric = window->Document()->Metric();
    QCOMPARE(QString(metric->GetDataDirectory()), metricFolder);
    QCOMPARE(QString::fromStdString(metric->GetFamilyName()), QString("tensor"));

    QString output;
    QVERIFY2(RunExportedScript(*window, folder, output), qPrintable(output));
    QVERIFY(window->SaveProject(project).isEmpty());
  }
  // The project lives in another folder than the volume: it keeps the
  // metric's folder, so it reopens.
  auto window = OpenWindow();
  QVERIFY(window);
  QCOMPARE(window->OpenFile(project, false), QString());
  QCOMPARE(QString(window->Document()->Metric()->GetDataDirectory()), metricFolder);
}

#include "TestStudio.moc"

void TestStudio::MovingTheCameraTracesFewerRaysUntilItStops()
{
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  // Ask for 10,000 frames a second while moving: no frame fits, so the pass
  // traces its fewest rays (one per 10 x 10 pixels) on any machine.
  inside->interactor()->SetDesiredUpdateRate(10000.0);
  QSignalSpy drawn(inside, &InsideView::ViewDrawn);
  // A real left drag (the trackball rotates the observer about its look-at point).
  auto send = [inside](QEvent::Type type, QPoint at, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, inside->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(inside, &event);
  };
  const QPoint start(120, 90);
  send(QEvent::MouseMove, start, Qt::NoButton);
  send(QEvent::MouseButtonPress, start, Qt::LeftButton);
  for (int k = 1; k <= 4; ++k)
  {
    send(QEvent::MouseMove, start + QPoint(6 * k, 3 * k), Qt::LeftButton);
  }
  QCoreApplication::processEvents();
  QVERIFY2(drawn.count() >= 2, qPrintable(QString("%1 frames while moving").arg(drawn.count())));
  QCOMPARE(drawn.last().at(0).toDouble(), 10.0);
  send(QEvent::MouseButtonRelease, start + QPoint(24, 12), Qt::NoButton);
  // The still frame that ends the drag comes in pieces (ProgressiveRefinement)
  // and ends full resolution: the picture a still render gives.
  QTRY_VERIFY_WITH_TIMEOUT(inside->Pass()->GetRefinementComplete(), 60000);
  QCoreApplication::processEvents();
  QCOMPARE(drawn.last().at(0).toDouble(), 1.0);
  const QImage released = inside->grabFramebuffer();
  inside->RenderNow();
  QCOMPARE(DifferentPixels(released, inside->grabFramebuffer()), 0.0);
}

void TestStudio::HoldingASliderTracesFewerRaysUntilItIsLetGo()
{
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  inside->interactor()->SetDesiredUpdateRate(10000.0); // no frame fits: the fewest rays
  QSignalSpy drawn(inside, &InsideView::ViewDrawn);
  QSlider* slider = window->Parameters()->Slider("/parameters/a");
  QVERIFY(slider);
  // Held and moved: every frame is coarse, and says so in the status bar.
  Q_EMIT slider->sliderPressed();
  slider->setValue(slider->value() + 40);
  QTRY_VERIFY(drawn.count() >= 1);
  QCOMPARE(drawn.last().at(0).toDouble(), 10.0);
  QVERIFY2(window->FrameTimeText().startsWith("moving: 1 ray per 10.0 x 10.0 pixels"),
    qPrintable(window->FrameTimeText()));
  // An export while it is held is still a full frame.
  const QImage captured = inside->Capture();
  QCOMPARE(drawn.last().at(0).toDouble(), 1.0);
  // Let go: a still frame, refined in pieces until every ray is traced.
  Q_EMIT slider->sliderReleased();
  const int before = drawn.count();
  QTRY_VERIFY(drawn.count() > before);
  QTRY_VERIFY_WITH_TIMEOUT(inside->Pass()->GetRefinementComplete(), 60000);
  QCoreApplication::processEvents();
  QCOMPARE(drawn.last().at(0).toDouble(), 1.0);
  QVERIFY2(window->FrameTimeText().startsWith("frame "), qPrintable(window->FrameTimeText()));
  QCOMPARE(DifferentPixels(captured, inside->grabFramebuffer()), 0.0);
}

/// From a finished still picture of the inside view, move the parameter
/// slider "a" and wait for the first picture after it (`drawn` spies on
/// InsideView::ViewDrawn). False when either does not come.
bool MoveSliderFromAFinishedPicture(StudioMainWindow& window, QSignalSpy& drawn)
{
  InsideView* inside = window.Inside();
  if (!QTest::qWaitFor([inside]() { return inside->Pass()->GetRefinementComplete(); }, 60000))
  {
    return false;
  }
  drawn.clear();
  QSlider* slider = window.Parameters()->Slider("/parameters/a");
  if (!slider)
  {
    return false;
  }
  // Returns at the first picture, before the next piece is traced: waiting
  // with QTest::qWaitFor would handle every piece already queued, and a fast
  // machine could finish the picture meanwhile.
  QEventLoop firstPicture;
  const auto quit =
    QObject::connect(inside, &InsideView::ViewDrawn, &firstPicture, &QEventLoop::quit);
  QTimer::singleShot(5000, &firstPicture, &QEventLoop::quit);
  slider->setValue(slider->value() + 40);
  if (drawn.count() < 1)
  {
    firstPicture.exec();
  }
  QObject::disconnect(quit);
  return drawn.count() >= 1;
}

void TestStudio::StillFramesComeInPiecesAndTheWindowAnswers()
{
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  QVERIFY(QTest::qWaitFor([inside]() { return inside->Pass()->GetRefinementComplete(); }, 60000));
  // What the window says when the first picture comes, and whether an event
  // posted then is handled before the picture is finished, are recorded in
  // the signal itself: waiting in the test processes every pending piece,
  // so a fast machine could finish the picture before the test looks.
  QString firstText;
  bool answered = false;
  bool answeredBeforeFinished = false;
  QObject::connect(inside, &InsideView::ViewDrawn, window.get(), [&, inside](double) {
    if (!firstText.isEmpty())
    {
      return;
    }
    firstText = window->FrameTimeText();
    QTimer::singleShot(0, window.get(), [&, inside]() {
      answered = true;
      answeredBeforeFinished = !inside->Pass()->GetRefinementComplete();
    });
  });
  QSignalSpy drawn(inside, &InsideView::ViewDrawn);
  // A slider let go at a new value: the first picture is a coarse lattice
  // (llvmpipe cannot trace the whole view in the 0.1 s a piece may take).
  QVERIFY(MoveSliderFromAFinishedPicture(*window, drawn));
  QVERIFY2(drawn.first().at(0).toDouble() >= 2.0,
    qPrintable(QString("first picture at %1").arg(drawn.first().at(0).toDouble())));
  QVERIFY2(firstText.startsWith("refining: 1 ray per"), qPrintable(firstText));
  // The event posted with the first picture is handled before the next
  // piece: the window answers between pieces.
  QTRY_VERIFY(answered);
  QVERIFY(answeredBeforeFinished);
  // The lattices get finer until every pixel has its ray: the still render's picture.
  QTRY_VERIFY_WITH_TIMEOUT(inside->Pass()->GetRefinementComplete(), 120000);
  QCoreApplication::processEvents();
  QCOMPARE(drawn.last().at(0).toDouble(), 1.0);
  for (int k = 1; k < drawn.count(); ++k)
  {
    QVERIFY(drawn.at(k).at(0).toDouble() <= drawn.at(k - 1).at(0).toDouble());
  }
  const QImage refined = inside->grabFramebuffer();
  inside->Pass()->ProgressiveRefinementOff();
  inside->RenderNow();
  QCOMPARE(DifferentPixels(refined, inside->grabFramebuffer()), 0.0);
}

void TestStudio::WindowScreenshotWaitsForTheFinishedPicture()
{
  // `riemann-studio --screenshot` (the whole window) once saved the inside
  // view at whichever lattice it had reached: "refining: 1 ray per 2.0 x 2.0
  // pixels" in the status bar of the picture.
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  QSignalSpy drawn(inside, &InsideView::ViewDrawn);
  QVERIFY(MoveSliderFromAFinishedPicture(*window, drawn));
  QVERIFY(!inside->Pass()->GetRefinementComplete());
  QTemporaryDir folder;
  const QString path = folder.filePath("window.png");
  QCOMPARE(window->SaveScreenshot(path, StudioMainWindow::WindowShot), QString());
  QVERIFY(inside->Pass()->GetRefinementComplete());
  QVERIFY2(window->FrameTimeText().startsWith("frame "), qPrintable(window->FrameTimeText()));
  QVERIFY(!QImage(path).isNull());
}

void TestStudio::TheWheelPreviewsThenRefines()
{
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  QTRY_VERIFY_WITH_TIMEOUT(inside->Pass()->GetRefinementComplete(), 60000);
  inside->interactor()->SetDesiredUpdateRate(10000.0); // no frame fits: the fewest rays
  QSignalSpy drawn(inside, &InsideView::ViewDrawn);
  double before[3];
  window->Document()->Observer()->GetPosition(before);
  // One wheel step forward: a dolly towards the look-at point.
  const QPoint at(120, 90);
  QWheelEvent wheel(at, inside->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(inside, &wheel);
  QCoreApplication::processEvents();
  double after[3];
  window->Document()->Observer()->GetPosition(after);
  QVERIFY(std::abs(after[2] - before[2]) + std::abs(after[0] - before[0]) > 1e-6);
  // The reduced preview a drag gets, then a still picture refined to the full one.
  QVERIFY2(drawn.count() >= 2, qPrintable(QString("%1 frames").arg(drawn.count())));
  QCOMPARE(drawn.first().at(0).toDouble(), 10.0);
  QTRY_VERIFY_WITH_TIMEOUT(inside->Pass()->GetRefinementComplete(), 120000);
  QCoreApplication::processEvents();
  QCOMPARE(drawn.last().at(0).toDouble(), 1.0);
}

void TestStudio::ProjectsTravelWithTheirFiles()
{
  // A project saved next to its scene names it relatively ("../scenes/...",
  // as Studio.md says), so the folder copied elsewhere opens there.
  QTemporaryDir first;
  QVERIFY(first.isValid());
  QVERIFY(QDir(first.path()).mkpath("scenes") && QDir(first.path()).mkpath("studio"));
  const QString scene = first.filePath("scenes/quick-scene.json");
  QVERIFY(QFile::rename(WriteQuickScene(first), scene));
  const QString project = first.filePath("studio/session.json");
  {
    auto window = OpenWindow();
    QVERIFY(window);
    QCOMPARE(window->OpenFile(scene, false), QString());
    QCOMPARE(window->SaveProject(project), QString());
  }
  QFile saved(project);
  QVERIFY(saved.open(QIODevice::ReadOnly));
  const nlohmann::json json = nlohmann::json::parse(saved.readAll().toStdString());
  QCOMPARE(QString::fromStdString(json.at("scene").at("file").get<std::string>()),
    QString("../scenes/quick-scene.json"));
  QVERIFY(!QDir::isAbsolutePath(QString::fromStdString(json.at("metric").value("folder", "."))));
  // Moved: the first folder is gone, the copy opens with its own scene.
  QTemporaryDir second;
  QVERIFY(QDir(second.path()).mkpath("scenes") && QDir(second.path()).mkpath("studio"));
  QVERIFY(QFile::copy(scene, second.filePath("scenes/quick-scene.json")));
  QVERIFY(QFile::copy(project, second.filePath("studio/session.json")));
  QVERIFY(first.remove());
  auto window = OpenWindow();
  QVERIFY(window);
  QCOMPARE(window->OpenFile(second.filePath("studio/session.json"), false), QString());
  QCOMPARE(QFileInfo(QString(window->Document()->Scene()->GetDefinitionFile())).canonicalFilePath(),
    QFileInfo(second.filePath("scenes/quick-scene.json")).canonicalFilePath());
}

void TestStudio::UnsavedChangesAreMarkedAndAsked()
{
  QTemporaryDir folder;
  auto window = OpenWindow(true); // as a user gets it: the helper's short rays are a change
  QVERIFY(window);
  // Fresh: nothing to save; the title has Qt's modified placeholder.
  QVERIFY(!window->IsDocumentModified());
  QVERIFY(window->windowTitle().contains("[*]"));
  window->Document()->AddItem("geodesics");
  QVERIFY(window->IsDocumentModified());
  QTRY_VERIFY_WITH_TIMEOUT(window->isWindowModified(), 3000);
  const QString project = folder.filePath("p.json");
  QCOMPARE(window->SaveProject(project), QString());
  QVERIFY(!window->IsDocumentModified());
  QTRY_VERIFY_WITH_TIMEOUT(!window->isWindowModified(), 3000);
  QCOMPARE(window->Session().Path(), project);
  QCOMPARE(window->Session().StartFolder(), QFileInfo(project).absolutePath());
  // Changed again, then closed: the question comes; Cancel keeps the
  // window open, Discard closes it.
  window->Document()->Observer()->Azimuth(15.0);
  window->Document()->ObserverChanged();
  QVERIFY(window->IsDocumentModified());
  const auto answer = [](QMessageBox::StandardButton button) {
    QTimer::singleShot(200, [button]() {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      if (box && box->objectName() == "UnsavedChangesQuestion")
      {
        box->button(button)->click();
      }
    });
  };
  answer(QMessageBox::Cancel);
  QVERIFY(!window->close());
  QVERIFY(window->isVisible());
  answer(QMessageBox::Discard);
  QVERIFY(window->close());
  // The file kept the first version (Discard wrote nothing).
  QFile saved(project);
  QVERIFY(saved.open(QIODevice::ReadOnly));
  const nlohmann::json json = nlohmann::json::parse(saved.readAll().toStdString());
  QCOMPARE(int(json.at("items").size()), 1);
}

void TestStudio::RecentFilesAndShippedProjects()
{
  auto window = OpenWindow();
  QVERIFY(window);
  const QString metric = DataFile("metrics/twist.json");
  const QString project = DataFile("studio/gaussian-bump-session.json");
  QCOMPARE(window->OpenFile(metric, false), QString());
  QCOMPARE(window->OpenFile(project, false), QString());
  const QStringList recent = ProjectSession::RecentFiles();
  QVERIFY(recent.size() >= 2);
  QCOMPARE(recent.at(0), QFileInfo(project).absoluteFilePath());
  QCOMPARE(recent.at(1), QFileInfo(metric).absoluteFilePath());
  // Opened, not modified; File > Open Recent lists both; Examples > Projects the shipped one.
  QVERIFY(!window->IsDocumentModified());
  auto* recentMenu = window->findChild<QMenu*>("RecentFilesMenu");
  QVERIFY(recentMenu);
  QMetaObject::invokeMethod(recentMenu, "aboutToShow");
  QVERIFY(recentMenu->actions().size() >= 2);
  QVERIFY(recentMenu->actions().at(0)->text().contains("gaussian-bump-session.json"));
  auto* examples = window->findChild<QMenu*>("ExamplesMenu");
  QVERIFY(examples);
  QStringList projects;
  for (QAction* action : examples->actions())
  {
    if (action->menu() && action->text() == "Projects")
    {
      for (QAction* entry : action->menu()->actions())
      {
        projects << entry->text();
      }
    }
  }
  QVERIFY2(projects.contains("gaussian-bump-session"), qPrintable(projects.join(", ")));
  // Save As has Ctrl+Shift+S whatever the platform's key bindings.
  bool saveAs = false;
  for (QAction* action : window->findChildren<QAction*>())
  {
    saveAs = saveAs || (action->text().startsWith("Save Project &As") &&
                         action->shortcuts().contains(QKeySequence("Ctrl+Shift+S")));
  }
  QVERIFY(saveAs);
}

void TestStudio::HiddenItemsDoNotCompute()
{
  auto window = OpenWindow();
  QVERIFY(window);
  StudioDocument* document = window->Document();
  PipelineItem* geodesics = document->AddItem("geodesics");
  window->Settle();
  QVERIFY(!document->IsStale(geodesics));
  // Hidden, then the metric changes: no job starts, the item is stale.
  geodesics->SetVisible(false);
  QSignalSpy finished(document, &StudioDocument::ItemFinished);
  QVERIFY(document->SetParameterValue("/parameters/a", 0.4).Ok());
  QCOMPARE(document->Jobs()->NumberOfRunningJobs(), 0);
  QVERIFY(!document->Jobs()->IsRunning(geodesics));
  QVERIFY(document->IsStale(geodesics));
  window->Settle();
  QCOMPARE(finished.count(), 0);
  // Shown: it computes for the metric as it is now.
  geodesics->SetVisible(true);
  QVERIFY(!document->IsStale(geodesics));
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
  QCOMPARE(finished.first().at(1).toBool(), true);
}

void TestStudio::HelpMenuListsShortcutsAndGuides()
{
  auto window = OpenWindow();
  QVERIFY(window);
  const QStringList shortcuts = KeyboardShortcuts(window->menuBar());
  const QString all = shortcuts.join("\n");
  QVERIFY2(all.contains("File > Save Project As...: Ctrl+Shift+S"), qPrintable(all));
  QVERIFY2(all.contains("File > Open...: Ctrl+O"), qPrintable(all));
  // The guides the menu opens are the ones in this tree.
  const QString data = QFileInfo(DataFile("metrics")).absolutePath();
  for (const char* name : { "Studio.md", "MetricFormat.md" })
  {
    QVERIFY2(QFileInfo::exists(DocumentationPath(data, name)), qPrintable(DocumentationPath(data, name)));
  }
  auto* help = window->findChild<QMenu*>("HelpMenu");
  QVERIFY(help);
  QStringList entries;
  for (QAction* action : help->actions())
  {
    entries << QString(action->text()).remove('&');
  }
  QVERIFY2(entries.contains("Riemann Studio Guide") && entries.contains("Metric Format") &&
      entries.contains("Keyboard Shortcuts"),
    qPrintable(entries.join(", ")));
}

void TestStudio::UndoAndRedoEveryKindOfChange()
{
  QTemporaryDir folder;
  auto window = OpenWindow();
  QVERIFY(window);
  QCOMPARE(window->OpenFile(WriteQuickScene(folder), false), QString()); // a new document: no history
  StudioDocument* document = window->Document();
  QUndoStack* stack = window->UndoStack();
  QCOMPARE(stack->count(), 0);
  std::vector<std::string> states = { ProjectFingerprint(*document) };
  QStringList names;
  // Each change, then the events after it: one command, named.
  const auto changed = [&](const QString& name) {
    QCoreApplication::processEvents();
    states.push_back(ProjectFingerprint(*document));
    names << name;
    return stack->count() == int(states.size()) - 1 && stack->undoText() == name;
  };
  PipelineItem* item = document->AddItem("geodesics");
  const QString first = item->Name(); // "Geodesics1"
  QVERIFY2(changed("Add " + first), qPrintable(stack->undoText()));
  item->SetName("Fan");
  QVERIFY2(changed("Rename " + first + " to Fan"), qPrintable(stack->undoText()));
  item->SetVisible(false);
  QVERIFY2(changed("Hide Fan"), qPrintable(stack->undoText()));
  QVERIFY(item->ApplySettings({ { "NumberOfDirections", 5 } }).isEmpty());
  QVERIFY2(changed("Apply Fan Properties"), qPrintable(stack->undoText()));
  // A slider dragged: its steps merge into one command.
  QVERIFY(document->SetParameterValue("/parameters/a", 0.5).Ok());
  QCoreApplication::processEvents();
  QVERIFY(document->SetParameterValue("/parameters/a", 0.45).Ok());
  QVERIFY2(changed("Set a"), qPrintable(stack->undoText()));
  nlohmann::json metric = nlohmann::json::parse(document->MetricText());
  metric["gaussians"][0]["sigma"] = 0.7;
  window->Editor()->SetText(QString::fromStdString(metric.dump(2)));
  QVERIFY2(changed("Edit Metric"), qPrintable(stack->undoText()));
  document->Observer()->Azimuth(12.0);
  document->ObserverChanged();
  QVERIFY2(changed("Move Observer"), qPrintable(stack->undoText()));
  document->RemoveItem(item);
  QVERIFY2(changed("Delete Fan"), qPrintable(stack->undoText()));
  // Undo to the start: after each, the document is the one before (its project text).
  for (int i = int(states.size()) - 1; i > 0; --i)
  {
    QCOMPARE(stack->undoText(), names[i - 1]);
    stack->undo();
    QCoreApplication::processEvents();
    QVERIFY2(ProjectFingerprint(*document) == states[i - 1],
      qPrintable(names[i - 1] + "\nnow:    " + QString::fromStdString(ProjectFingerprint(*document)) +
        "\nbefore: " + QString::fromStdString(states[i - 1])));
  }
  QCOMPARE(stack->count(), int(states.size()) - 1); // undoing recorded nothing new
  // And redo to the end.
  for (std::size_t i = 1; i < states.size(); ++i)
  {
    stack->redo();
    QCoreApplication::processEvents();
    QVERIFY2(ProjectFingerprint(*document) == states[i], qPrintable(names[int(i) - 1]));
  }
  // Edit > Undo names the change; Ctrl+Z and Ctrl+Shift+Z / Ctrl+Y are its keys.
  auto* edit = window->findChild<QMenu*>("EditMenu");
  QVERIFY(edit);
  QCOMPARE(QString(edit->actions().at(0)->text()).remove('&'), QString("Undo Delete Fan"));
  QVERIFY(edit->actions().at(0)->shortcuts().contains(QKeySequence("Ctrl+Z")));
  QVERIFY(edit->actions().at(1)->shortcuts().contains(QKeySequence("Ctrl+Shift+Z")));
  QVERIFY(edit->actions().at(1)->shortcuts().contains(QKeySequence("Ctrl+Y")));
}

void TestStudio::ColourMapEditorIsAppliedAndSaved()
{
  QTemporaryDir folder;
  const QString project = folder.filePath("colours.json");
  const nlohmann::json colours = { { "ColorArray", "ArcLength" }, { "ColorMap", "magma" },
    { "ColorRange", "custom" }, { "ColorRangeMinimum", 0.5 }, { "ColorRangeMaximum", 2.0 },
    { "ColorSteps", 5 }, { "ScalarBar", true } };
  // The lookup table and legend an item shows for `colours`.
  const auto check = [](OutsideView* view, PipelineItem* item) {
    vtkScalarBarActor* bar = view->DisplayOf(item)->ScalarBar();
    QVERIFY(bar->GetVisibility());
    auto* table = vtkLookupTable::SafeDownCast(bar->GetLookupTable());
    QVERIFY(table);
    QCOMPARE(int(table->GetNumberOfTableValues()), 5);
    QCOMPARE(table->GetTableRange()[0], 0.5);
    QCOMPARE(table->GetTableRange()[1], 2.0);
    QCOMPARE(QString(bar->GetTitle()), QString("ArcLength"));
    // magma's first band (its value at 0.1 of the range) is dark purple.
    double rgb[4];
    table->GetTableValue(0, rgb);
    QVERIFY2(rgb[0] < 0.15 && rgb[1] < 0.1 && rgb[2] < 0.35, qPrintable(QString("%1 %2 %3").arg(rgb[0]).arg(rgb[1]).arg(rgb[2])));
  };
  {
    auto window = OpenWindow();
    QVERIFY(window);
    QVERIFY(ColorMapNames().startsWith("viridis"));
    for (const char* name : { "cividis", "magma", "cool-to-warm", "vtk-rainbow" })
    {
      QVERIFY(ColorMapNames().contains(name));
    }
    PipelineItem* geodesics = window->Document()->AddItem("geodesics");
    QCOMPARE(QString::fromStdString(geodesics->Settings().at("ColorMap").get<std::string>()), QString("viridis"));
    window->Settle();
    QVERIFY(!window->Outside()->DisplayOf(geodesics)->ScalarBar()->GetVisibility());
    QCOMPARE(geodesics->ApplySettings(colours), QString());
    window->Settle();
    check(window->Outside(), geodesics);
    // Hidden item, hidden legend; shown again, back.
    geodesics->SetVisible(false);
    QVERIFY(!window->Outside()->DisplayOf(geodesics)->ScalarBar()->GetVisibility());
    geodesics->SetVisible(true);
    window->Settle();
    QVERIFY(window->Outside()->DisplayOf(geodesics)->ScalarBar()->GetVisibility());
    QCOMPARE(window->SaveProject(project), QString());
  }
  auto window = OpenWindow();
  QVERIFY(window);
  QCOMPARE(window->OpenFile(project, false), QString());
  window->Settle();
  PipelineItem* reopened = window->Document()->Items().front().get();
  for (const auto& setting : colours.items())
  {
    QVERIFY2(reopened->Settings().at(setting.key()) == setting.value(), setting.key().c_str());
  }
  check(window->Outside(), reopened);
}

void TestStudio::SpreadsheetAndCsvExportShowThePoints()
{
  QTemporaryDir folder;
  auto window = OpenWindow();
  QVERIFY(window);
  PipelineItem* geodesics = window->Document()->AddItem("geodesics");
  QVERIFY(geodesics->ApplySettings({ { "NumberOfDirections", 3 }, { "MaximumPropagation", 1.0 } }).isEmpty());
  window->Settle();
  auto* lines = vtkPolyData::SafeDownCast(geodesics->Result(0));
  QVERIFY(lines && lines->GetNumberOfPoints() > 10);
  // View > Spreadsheet, the item selected: one row per point, coordinates and arrays.
  window->SpreadsheetDock()->show();
  window->Browser()->Select(geodesics);
  QCoreApplication::processEvents();
  QTableWidget* table = window->Spreadsheet()->Table();
  QCOMPARE(table->rowCount(), int(lines->GetNumberOfPoints()));
  QStringList columns;
  for (int c = 0; c < table->columnCount(); ++c)
  {
    columns << table->horizontalHeaderItem(c)->text();
  }
  QVERIFY2(columns.mid(0, 3) == QStringList({ "Points_X", "Points_Y", "Points_Z" }), qPrintable(columns.join(",")));
  QVERIFY2(columns.contains("ArcLength") && columns.contains("Velocity_0"), qPrintable(columns.join(",")));
  double p[3];
  lines->GetPoint(5, p);
  QCOMPARE(table->item(5, 1)->text().toDouble(), QString::number(p[1], 'g', 8).toDouble());
  QVERIFY(window->Spreadsheet()->Title().contains(QString::number(lines->GetNumberOfPoints()) + " points"));
  // Exported as CSV: a header, then the same rows, whole.
  const QString csv = folder.filePath("fan.csv");
  QCOMPARE(window->ExportItemData(geodesics, csv), QString());
  QFile file(csv);
  QVERIFY(file.open(QIODevice::ReadOnly));
  const QStringList rows = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
  QCOMPARE(rows.size(), int(lines->GetNumberOfPoints()) + 1);
  QVERIFY2(rows.first().startsWith("Points_X,Points_Y,Points_Z"), qPrintable(rows.first()));
  QCOMPARE(rows.at(6).split(',').at(1).toDouble(), p[1]);
}

void TestStudio::TwoPointsOnThePickedRayMeasureItsArcLength()
{
  auto window = OpenWindow();
  QVERIFY(window);
  int width, height;
  window->Inside()->PixelSize(width, height);
  window->PickPixel(width / 2, height / 2);
  vtkPolyData* ray = window->PickedRay();
  QVERIFY(ray->GetNumberOfPoints() > 30);
  vtkDataArray* arc = ray->GetPointData()->GetArray("ArcLength");
  QVERIFY(arc);
  QVERIFY(std::isnan(window->MeasuredArcLength()));
  // Nothing selected: two Ctrl+clicks (near points 5 and 25 of the ray) measure.
  window->Browser()->SelectMetric();
  double a[3], b[3];
  ray->GetPoint(5, a);
  ray->GetPoint(25, b);
  window->PlacePoint(a[0] + 1e-4, a[1], a[2]);
  QVERIFY(std::isnan(window->MeasuredArcLength()));
  window->PlacePoint(b[0], b[1] - 1e-4, b[2]);
  QCOMPARE(window->MeasuredArcLength(), std::abs(arc->GetComponent(25, 0) - arc->GetComponent(5, 0)));
  QVERIFY2(window->StatusText().contains("Arc length along the picked ray from its point 5 to 25"),
    qPrintable(window->StatusText()));
}

void TestStudio::AnimationFliesAlongACameraPathToFramesAndAFilm()
{
  auto window = OpenWindow();
  QVERIFY(window);
  StudioDocument* document = window->Document();
  // A camera path item: Ctrl+clicks add keys and make it a spline flight.
  PipelineItem* path = document->AddItem("camera-path");
  QVERIFY(path);
  for (const auto& key : { std::array<double, 3>{ 0.5, 0.5, 3.6 }, std::array<double, 3>{ 0.3, 0.4, 2.6 },
         std::array<double, 3>{ 0.6, 0.2, 1.6 } })
  {
    QVERIFY(path->TakePickedPoint(key.data()));
  }
  QCOMPARE(QString::fromStdString(path->Settings().at("PathType").get<std::string>()), QString("spline"));
  QCOMPARE(path->Settings().at("KeyPositions").size(), std::size_t(3));
  path->ApplySettings({ { "NumberOfFrames", 12 } });
  QVERIFY(WaitForJobs(*window));
  // Its frames: g-orthonormal along the path (the transport keeps them so).
  auto* frames = vtkPolyData::SafeDownCast(path->Result(0));
  QVERIFY(frames);
  QCOMPARE(frames->GetNumberOfPoints(), vtkIdType(12));
  double worst = 0.0;
  for (vtkIdType k = 0; k < frames->GetNumberOfPoints(); ++k)
  {
    double p[3], g[9], e[3][3];
    frames->GetPoint(k, p);
    QVERIFY(document->Metric()->EvaluateMetricTensor(p, g));
    const char* names[3] = { "Forward", "Up", "Right" };
    for (int i = 0; i < 3; ++i)
    {
      frames->GetPointData()->GetArray(names[i])->GetTuple(k, e[i]);
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        double gij = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          for (int b = 0; b < 3; ++b)
          {
            gij += e[i][a] * g[3 * a + b] * e[j][b];
          }
        }
        worst = std::max(worst, std::abs(gij - (i == j ? 1.0 : 0.0)));
      }
    }
  }
  QVERIFY2(worst < 1e-9, qPrintable(QString("g-orthonormality error %1").arg(worst)));

  // The animation along it: a film read back by the Theora decoder.
  double observer[3];
  document->Observer()->GetPosition(observer);
  const double time = document->Time();
  const int steps = window->UndoStack()->count();
  QTemporaryDir folder;
  AnimationSettings animation;
  animation.Frames = 5;
  animation.Width = 96;
  animation.Height = 64;
  animation.CameraPath = path->Name();
  animation.Output = folder.filePath("flight.ogv");
  int reported = 0;
  QCOMPARE(ExportAnimation(*window, animation, [&reported](int done, int total) {
    reported = done;
    return total == 5;
  }),
    QString());
  QCOMPARE(reported, 5);
  const QString reader = QCoreApplication::applicationDirPath() + "/riemann-film-frames";
  if (QFileInfo::exists(reader))
  {
    QProcess decode;
    decode.start(reader, { animation.Output });
    QVERIFY(decode.waitForFinished(60000));
    QCOMPARE(decode.exitCode(), 0);
    const QStringList lines = QString::fromUtf8(decode.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
    QVERIFY(!lines.isEmpty());
    QCOMPARE(lines.first(), QString("frames 5 width 96 height 64"));
    QVERIFY(lines.at(1) != lines.at(5)); // the first and last frames differ: the observer flew
  }
  else
  {
    qWarning("riemann-film-frames not built: the film's frames are not read back");
  }
  // Everything put back: the observer, t, and no undo steps for the export.
  double after[3];
  document->Observer()->GetPosition(after);
  QCOMPARE(after[0], observer[0]);
  QCOMPARE(after[1], observer[1]);
  QCOMPARE(after[2], observer[2]);
  QCOMPARE(document->Time(), time);
  QCOMPARE(window->UndoStack()->count(), steps);

  // Both views at a chosen size, as numbered pictures; the first frame is
  // the flight's start.
  animation.Frames = 2;
  animation.View = StudioMainWindow::BothShot;
  animation.Width = 200;
  animation.Height = 80;
  animation.Output = folder.filePath("both.png");
  QCOMPARE(ExportAnimation(*window, animation), QString());
  QCOMPARE(QImage(folder.filePath("both_0000.png")).size(), QSize(200, 80));
  QCOMPARE(QImage(folder.filePath("both_0001.png")).size(), QSize(200, 80));

  // Cancelled after the first frame: nothing is left, neither film nor pictures.
  QTemporaryDir empty;
  for (const char* name : { "cancelled.ogv", "cancelled.png" })
  {
    animation.Frames = 4;
    animation.Output = empty.filePath(name);
    QCOMPARE(ExportAnimation(*window, animation, [](int done, int) { return done < 1; }),
      QString("cancelled"));
  }
  QCOMPARE(QDir(empty.path()).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot), QStringList());
  // Bad requests are refused before anything moves.
  animation.Output = empty.filePath("film.avi");
  QVERIFY(ExportAnimation(*window, animation).contains(".png pictures or one .ogv film"));
  animation.Output = empty.filePath("odd.ogv");
  animation.Width = 101;
  QVERIFY(ExportAnimation(*window, animation).contains("even sides"));
}

void TestStudio::PythonShellRunsLinesAndScripts()
{
  auto window = OpenWindow();
  QVERIFY(window);
  PythonShell* shell = window->Shell();
  QVERIFY(shell);
  QVERIFY2(shell->Input()->isEnabled(), qPrintable(shell->Transcript()));
  // Lines as typed: an expression shows its value, a block waits for its end.
  QVERIFY(!shell->Enter("x = 6 * 7"));
  QVERIFY(!shell->Enter("x"));
  QVERIFY2(shell->Transcript().contains("\n42\n"), qPrintable(shell->Transcript()));
  QVERIFY(shell->Enter("for i in range(2):"));
  QVERIFY(shell->Enter("    print('line', i)"));
  QVERIFY(!shell->Enter(""));
  QVERIFY(shell->Transcript().contains("line 0\nline 1\n"));
  // The studio module drives this window; errors show as tracebacks.
  QVERIFY(!shell->Enter("studio.add('geodesics', NumberOfDirections=3)"));
  QCOMPARE(window->Document()->Items().size(), std::size_t(1));
  QVERIFY(shell->Transcript().contains("'Geodesics1'"));
  QVERIFY(!shell->Enter("studio.set('Geodesics1', ConeAngle=400)"));
  QVERIFY(shell->Transcript().contains("StudioError: Geodesics1: Cone angle: must be in [0, 180]"));
  QVERIFY(!shell->Enter("1 / 0"));
  QVERIFY(shell->Transcript().contains("ZeroDivisionError"));
  QVERIFY(!shell->Enter("studio.undo()"));
  QCOMPARE(window->Document()->Items().size(), std::size_t(0));
  // The same modules as scripts.
  QVERIFY(!shell->Enter("import riemann; print(riemann.vtkRiemannCameraPath.__name__)"));
  QVERIFY2(shell->Transcript().contains("\nvtkRiemannCameraPath\n"), qPrintable(shell->Transcript()));
  // Up brings the last line back.
  QTest::keyClick(shell->Input(), Qt::Key_Up);
  QCOMPARE(shell->Input()->text(), QString("import riemann; print(riemann.vtkRiemannCameraPath.__name__)"));

  // --script ... --exit: the script's status, its traceback on stderr.
  const QString studio = QCoreApplication::applicationDirPath() + "/riemann-studio";
  QTemporaryDir folder;
  const QString failing = folder.filePath("failing.py");
  QFile file(failing);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write("import studio\nprint('items', studio.items())\n1 / 0\n");
  file.close();
  QProcess run;
  run.start(studio, { "--size", "320x240", "--script", failing, "--exit" });
  QVERIFY(run.waitForFinished(120000));
  QCOMPARE(run.exitCode(), 1);
  QVERIFY(QString::fromUtf8(run.readAllStandardOutput()).contains("items []"));
  QVERIFY(QString::fromUtf8(run.readAllStandardError()).contains("ZeroDivisionError"));
  run.start(studio, { "--exit" });
  QVERIFY(run.waitForFinished(60000));
  QCOMPARE(run.exitCode(), 2);
  QVERIFY(QString::fromUtf8(run.readAllStandardError()).contains("--exit ends a --script run"));
}

namespace
{
/// Every message VTK would print (errors, warnings) while it is installed.
class MessageCatcher : public vtkOutputWindow
{
public:
  static MessageCatcher* New();
  vtkTypeMacro(MessageCatcher, vtkOutputWindow);
  void DisplayText(const char* text) override { this->Messages << QString::fromUtf8(text); }
  QStringList Messages;
};
vtkStandardNewMacro(MessageCatcher);
}

void TestStudio::CancelledCpuRenderKeepsThePicture()
{
  auto window = OpenWindow();
  QVERIFY(window);
  InsideView* inside = window->Inside();
  inside->SetBackend(InsideView::CPU);
  window->Settle();
  const QImage before = inside->grabFramebuffer();
  QVERIFY(DistinctColors(before) > 5); // a traced picture, not a cleared view
  vtkNew<MessageCatcher> catcher;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(catcher);
  // A new picture asked for (the observer moved, 64 samples a pixel: seconds),
  // then cancelled at once: the last picture stays, and VTK says nothing.
  inside->SetSamplesPerPixel(64);
  double position[3];
  window->Document()->Observer()->GetPosition(position);
  window->Document()->Observer()->SetPosition(position[0] + 0.05, position[1], position[2]);
  window->Document()->ObserverChanged();
  QTRY_VERIFY(window->Document()->Jobs()->NumberOfRunningJobs() > 0);
  QElapsedTimer cancelling;
  cancelling.start();
  window->Document()->CancelAll();
  QTRY_COMPARE_WITH_TIMEOUT(window->Document()->Jobs()->NumberOfRunningJobs(), 0, 30000);
  qInfo("the cancelled 64-sample CPU render stopped in %lld ms", cancelling.elapsed());
  QCoreApplication::processEvents();
  inside->renderWindow()->Render();
  const QImage after = inside->grabFramebuffer();
  vtkOutputWindow::SetInstance(previous);
  QVERIFY2(catcher->Messages.isEmpty(), qPrintable(catcher->Messages.join("\n")));
  QCOMPARE(after.size(), before.size());
  QCOMPARE(DifferentPixels(before, after), 0.0);
}

void TestStudio::ColourRangeOverTimeSpansEveryT()
{
  auto window = OpenWindow();
  QVERIFY(window);
  StudioDocument* document = window->Document();
  // The bump grows with t: its curvature's range too.
  QCOMPARE(window->Editor()->SetText(
             R"json({"type": "graph", "parameters": {"a": {"from": 0.2, "to": 1.5}},)json"
             R"json( "f": "a * exp(-(x^2 + y^2 + z^2) / 0.5)"})json"),
    QString());
  PipelineItem* field = document->AddItem("field");
  QVERIFY(field->ApplySettings({ { "Dimensions", { 9, 9, 9 } } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  // The range the item's results take at t = 0, 1/8, ..., 1, one t at a time.
  double expected[2] = { 1e300, -1e300 };
  double atZero[2] = { 0.0, 0.0 };
  for (int k = 0; k < 9; ++k)
  {
    QVERIFY(document->SetTime(k / 8.0).Ok());
    QVERIFY(WaitForJobs(*window));
    auto* image = vtkImageData::SafeDownCast(field->Result(0));
    QVERIFY(image);
    double range[2];
    image->GetPointData()->GetArray("ScalarCurvature")->GetRange(range);
    if (k == 0)
    {
      atZero[0] = range[0];
      atZero[1] = range[1];
    }
    expected[0] = std::min(expected[0], range[0]);
    expected[1] = std::max(expected[1], range[1]);
  }
  QVERIFY(document->SetTime(0.0).Ok());
  QVERIFY(WaitForJobs(*window));
  QVERIFY(!field->CurrentColoring().CustomRange); // "data" so far
  // Over time: sampled in the background, then the colouring's range.
  QVERIFY(field->ApplySettings({ { "ColorRange", "over time" } }).isEmpty());
  QVERIFY(WaitForJobs(*window));
  ColorScale scale = field->CurrentColoring();
  QVERIFY(scale.CustomRange);
  QVERIFY2(std::abs(scale.Minimum - expected[0]) < 1e-12 && std::abs(scale.Maximum - expected[1]) < 1e-12,
    qPrintable(QString("over time [%1, %2], expected [%3, %4]")
                 .arg(scale.Minimum).arg(scale.Maximum).arg(expected[0]).arg(expected[1])));
  QVERIFY(scale.Maximum > atZero[1] + 1e-3 || scale.Minimum < atZero[0] - 1e-3); // wider than t = 0's
  // t alone changes the data, not the range over time, and samples nothing.
  QVERIFY(document->SetTime(0.5).Ok());
  QVERIFY(!document->Jobs()->IsRunning(field->TimeRangeKey()));
  QVERIFY(WaitForJobs(*window));
  QCOMPARE(field->CurrentColoring().Minimum, scale.Minimum);
  QCOMPARE(field->CurrentColoring().Maximum, scale.Maximum);
  // Saved and opened again: still over time.
  QTemporaryDir folder;
  const QString project = folder.filePath("range.json");
  QCOMPARE(window->SaveProject(project), QString());
  QVERIFY(window->OpenFile(project, false).isEmpty());
  QVERIFY(WaitForJobs(*window));
  QCOMPARE(QString::fromStdString(
             document->Items().front()->Settings().at("ColorRange").get<std::string>()),
    QString("over time"));
  QVERIFY(document->Items().front()->CurrentColoring().CustomRange);
}

void TestStudio::CameraPathKeysAreDraggedInTheOutsideView()
{
  auto window = OpenWindow();
  QVERIFY(window);
  StudioDocument* document = window->Document();
  PipelineItem* path = document->AddItem("camera-path");
  QVERIFY(path->ApplySettings({ { "PathType", "spline" },
                                { "KeyPositions", { { 0.5, 0.5, 3.6 }, { 0.4, 0.4, 2.0 }, { 0.6, 0.3, 1.0 } } } })
            .isEmpty());
  QVERIFY(WaitForJobs(*window));
  OutsideView* outside = window->Outside();
  window->Browser()->SelectMetric();
  QCOMPARE(outside->NumberOfKeyHandles(), 0); // not selected
  window->Browser()->Select(path);
  QCOMPARE(outside->NumberOfKeyHandles(), 3);
  // A drag of the middle key's handle: the item's key, and its flight, follow.
  const std::string before = ProjectFingerprint(*document);
  const double to[3] = { 1.2, -0.3, 2.2 };
  outside->DragKey(1, to);
  const nlohmann::json keys = path->Settings().at("KeyPositions");
  QCOMPARE(keys[1][0].get<double>(), 1.2);
  QCOMPARE(keys[1][1].get<double>(), -0.3);
  QCOMPARE(keys[1][2].get<double>(), 2.2);
  QCOMPARE(keys[0][2].get<double>(), 3.6);
  QVERIFY(WaitForJobs(*window));
  // A Ctrl+click adds a fourth key, and a fourth handle.
  window->PlacePoint(0.5, 0.2, 0.0);
  QVERIFY(WaitForJobs(*window));
  QCOMPARE(path->Settings().at("KeyPositions").size(), std::size_t(4));
  QCOMPARE(outside->NumberOfKeyHandles(), 4);
  // Undo twice: the document before the drag.
  QCoreApplication::processEvents();
  window->UndoHistory()->Record();
  window->UndoStack()->undo();
  window->UndoStack()->undo();
  QVERIFY(WaitForJobs(*window));
  QCOMPARE(ProjectFingerprint(*document), before);
  // Another selection: no handles.
  window->Browser()->SelectMetric();
  QCOMPARE(outside->NumberOfKeyHandles(), 0);
}
