#include "StudioMainWindow.h"

#include "AnimationExport.h"
#include "PythonShell.h"

#include "DataTable.h"
#include "HelpMenu.h"
#include "RayMeasure.h"
#include "SpreadsheetView.h"

#include "IntegrationValues.h"
#include "PictureValues.h"

#include "GeodesicTrace.h"
#include "RungeKutta.h"

#include "InsideView.h"
#include "InsideViewRays.h"
#include "MetricEditor.h"
#include "OutsideView.h"
#include "ParameterPanel.h"
#include "PipelineBrowser.h"
#include "PipelineItems.h"
#include "ProjectFile.h"
#include "PropertiesPanel.h"
#include "PythonTrace.h"
#include "StudioDocument.h"
#include "TimeBar.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayBundle.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "vtkRiemannPictureSettings.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTable.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <QAction>
#include <QApplication>
#include <QBuffer>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QTimer>
#include <QCoreApplication>
#include <QPainter>
#include <QProgressBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QSplitter>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QVBoxLayout>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

namespace riemann
{
namespace studio
{
namespace
{
/// The folder of the shipped metrics and scenes.
QString DataDirectory()
{
  const QByteArray fromEnvironment = qgetenv("RIEMANN_DATA_DIR");
  if (!fromEnvironment.isEmpty())
  {
    return QString::fromLocal8Bit(fromEnvironment);
  }
  // An installed app: <prefix>/share/RiemannVTK/Data; a build tree: the source's Data.
  const QString installed = QCoreApplication::applicationDirPath() + "/../share/RiemannVTK/Data";
  return QFileInfo::exists(installed) ? installed : QStringLiteral(RIEMANN_STUDIO_DATA_DIR);
}

QString ReadText(const QString& path, QString& error)
{
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly))
  {
    error = QStringLiteral("%1: cannot open: %2").arg(path, file.errorString());
    return QString();
  }
  return QString::fromUtf8(file.readAll());
}

/// Names of vtkRiemannGeodesicTracer's termination codes (the bundle's too).
/// Why a picked ray ended, in the core's words (GeodesicTrace.h: every
/// code, "left the sampled data" included).
QString ReasonName(int reason)
{
  return QString::fromUtf8(riemann::TerminationReasonName(reason));
}
}

StudioMainWindow::StudioMainWindow(QWidget* parent)
  : QMainWindow(parent)
  , Doc(new StudioDocument(this))
{
  this->setObjectName("RiemannStudio");
  this->resize(1500, 900);
  this->InsideWidget = new InsideView(this->Doc, this);
  this->InsideWidget->setObjectName("InsideView");
  this->OutsideWidget = new OutsideView(this->Doc, this);
  this->OutsideWidget->setObjectName("OutsideView");
  this->Views = new QSplitter(Qt::Horizontal, this);
  this->Views->addWidget(this->InsideWidget);
  this->Views->addWidget(this->OutsideWidget);
  this->Views->setStretchFactor(0, 1);
  this->Views->setStretchFactor(1, 1);
  this->setCentralWidget(this->Views);

  this->BuildDocks();
  this->BuildStatusBar();
  // Undo and redo of every change to the document; after one, the editor
  // shows the metric text the document holds again.
  this->History = new DocumentHistory(this->Doc,
    [this]() {
      this->EditorWidget->SetText(QString::fromStdString(this->Doc->MetricText()));
      this->UpdateTitle();
    },
    this);
  // The modified mark follows the document whatever changed it (an item's
  // property, the observer, t, a slider): the history compares it with its
  // last state after every change, undo and redo.
  QObject::connect(this->History, &DocumentHistory::Compared, this, &StudioMainWindow::UpdateModifiedMark);
  this->BuildMenus();
  this->Project.MarkClean(ProjectFingerprint(*this->Doc));

  // Ctrl+click in the outside view places the selected item's points.
  QObject::connect(this->OutsideWidget, &OutsideView::PointPicked, this, &StudioMainWindow::PlacePoint);
  // The link between the views: a picked pixel's ray appears outside.
  QObject::connect(this->InsideWidget, &InsideView::PixelPicked, this, &StudioMainWindow::PickPixel);
  QObject::connect(this->InsideWidget, &InsideView::RenderFailed, this,
    [this](const QString& message) { this->ShowMessage("Inside view: " + message, true); });
  // While the view moves the pass traces fewer rays, and a still frame comes
  // coarse first (refined in pieces): say how many rays.
  const auto coarseText = [this](double distance) {
    const bool refining = !this->InsideWidget->Pass()->GetRefinementComplete();
    return QStringLiteral("%1: 1 ray per %2 x %2 pixels")
      .arg(refining ? QStringLiteral("refining") : QStringLiteral("moving"))
      .arg(distance, 0, 'f', 1);
  };
  QObject::connect(this->InsideWidget, &InsideView::ViewDrawn, this, [this, coarseText](double distance) {
    this->LastDistance = distance;
    this->FrameTime->setText(distance > 1.0 ? coarseText(distance) : this->LastFrameTime);
  });
  QObject::connect(this->InsideWidget, &InsideView::FrameRendered, this, [this, coarseText](double ms) {
    const QString time = QStringLiteral("frame %1 ms").arg(ms, 0, 'f', 1);
    if (this->LastDistance > 1.0)
    {
      this->FrameTime->setText(coarseText(this->LastDistance) + ", " + time);
      return;
    }
    this->LastFrameTime = time;
    this->FrameTime->setText(time);
  });
  // A held slider or playing t moves the view as the mouse does.
  QObject::connect(this->ParameterWidget, &ParameterPanel::Moving, this->InsideWidget, &InsideView::SetMoving);
  QObject::connect(this->TimeWidget, &TimeBar::Moving, this->InsideWidget, &InsideView::SetMoving);
  QObject::connect(this->Doc, &StudioDocument::ItemFinished, this, [this](PipelineItem* item, bool) {
    const QString error = this->Doc->ItemError(item);
    if (!error.isEmpty())
    {
      this->ShowMessage(item->Name() + ": " + error, true);
    }
    if (item == this->BrowserWidget->SelectedItem())
    {
      this->ShowSpreadsheet();
    }
    if (item == this->BrowserWidget->SelectedItem() && !this->PropertiesWidget->HasPendingEdits())
    {
      this->ShowSelection(); // new colouring arrays
    }
  });
  QObject::connect(this->Doc, &StudioDocument::MetricChanged, this, &StudioMainWindow::UpdateTitle);
  this->UpdateTitle();
  this->BrowserWidget->SelectScene();
}

StudioMainWindow::~StudioMainWindow()
{
  this->Doc->Jobs()->Close();
  // The views use the document (the inside view cancels its render in its
  // destructor), which is this window's first child and so would be
  // deleted before them: they go first.
  delete this->takeCentralWidget();
}

void StudioMainWindow::BuildDocks()
{
  this->BrowserWidget = new PipelineBrowser(this->Doc, this);
  this->PropertiesWidget = new PropertiesPanel(this);
  auto* left = new QSplitter(Qt::Vertical, this);
  left->addWidget(this->BrowserWidget);
  left->addWidget(this->PropertiesWidget);
  left->setStretchFactor(1, 2);
  auto* pipelineDock = new QDockWidget(QStringLiteral("Pipeline"), this);
  pipelineDock->setObjectName("PipelineDock");
  pipelineDock->setWidget(left);
  this->addDockWidget(Qt::LeftDockWidgetArea, pipelineDock);

  this->EditorWidget = new MetricEditor(this->Doc, this);
  this->ParameterWidget = new ParameterPanel(this->Doc, this);
  auto* right = new QSplitter(Qt::Vertical, this);
  right->addWidget(this->EditorWidget);
  right->addWidget(this->ParameterWidget);
  right->setStretchFactor(0, 3);
  auto* metricDock = new QDockWidget(QStringLiteral("Metric"), this);
  metricDock->setObjectName("MetricDock");
  metricDock->setWidget(right);
  this->addDockWidget(Qt::RightDockWidgetArea, metricDock);
  this->resizeDocks({ pipelineDock, metricDock }, { 330, 360 }, Qt::Horizontal);

  this->TimeWidget = new TimeBar(this->Doc, this);
  this->addToolBar(Qt::BottomToolBarArea, this->TimeWidget);

  // The spreadsheet: the selected item's points, else the picked ray's
  // (hidden at first, as ParaView opens it on demand: View > Spreadsheet).
  this->SheetWidget = new SpreadsheetView(this);
  this->SheetDock = new QDockWidget(QStringLiteral("Spreadsheet"), this);
  this->SheetDock->setObjectName("SpreadsheetDock");
  this->SheetDock->setWidget(this->SheetWidget);
  this->addDockWidget(Qt::BottomDockWidgetArea, this->SheetDock);
  this->SheetDock->hide();
  // The Python shell: the studio module and riemann, as in scripts.
  this->ShellWidget = new PythonShell(this, this);
  this->ShellDock = new QDockWidget(QStringLiteral("Python Shell"), this);
  this->ShellDock->setObjectName("PythonShellDock");
  this->ShellDock->setWidget(this->ShellWidget);
  this->addDockWidget(Qt::BottomDockWidgetArea, this->ShellDock);
  this->ShellDock->hide();
  QObject::connect(this->SheetDock, &QDockWidget::visibilityChanged, this,
    [this](bool shown) {
      if (shown)
      {
        this->ShowSpreadsheet();
      }
    });

  QObject::connect(this->BrowserWidget, &PipelineBrowser::SelectionChanged, this,
    &StudioMainWindow::ShowSelection);
  QObject::connect(this->BrowserWidget, &PipelineBrowser::DeleteRequested, this,
    [this](PipelineItem* item) { this->Doc->RemoveItem(item); });
  QObject::connect(this->EditorWidget, &MetricEditor::Checked, this,
    [this](bool ok, const QString& message) {
      this->ShowMessage(ok ? QStringLiteral("Metric applied") : "Metric: " + message, !ok);
    });
  QObject::connect(this->ParameterWidget, &ParameterPanel::ValueApplied, this,
    [this](bool ok, const QString& message) {
      if (!ok)
      {
        this->ShowMessage("Parameter: " + message, true);
      }
    });
  QObject::connect(this->TimeWidget, &TimeBar::TimeApplied, this,
    [this](bool ok, const QString& message) {
      if (!ok)
      {
        this->ShowMessage("Time: " + message, true);
      }
    });
  QObject::connect(
    this->TimeWidget, &TimeBar::ExportFramesRequested, this, &StudioMainWindow::AskExportAnimation);
}

void StudioMainWindow::BuildStatusBar()
{
  this->Message = new QLabel(this);
  this->Message->setObjectName("StatusMessage");
  this->FrameTime = new QLabel(this);
  this->Progress = new QProgressBar(this);
  this->Progress->setRange(0, 1000);
  this->Progress->setMaximumWidth(220);
  this->Progress->setVisible(false);
  this->Cancel = new QPushButton(QStringLiteral("Cancel"), this);
  this->Cancel->setObjectName("CancelButton");
  this->Cancel->setVisible(false);
  this->statusBar()->addWidget(this->Message, 1);
  this->statusBar()->addPermanentWidget(this->FrameTime);
  this->statusBar()->addPermanentWidget(this->Progress);
  this->statusBar()->addPermanentWidget(this->Cancel);
  JobRunner* jobs = this->Doc->Jobs();
  QObject::connect(jobs, &JobRunner::Progress, this, [this](const QString& label, double fraction) {
    this->Progress->setFormat(label + " %p%");
    this->Progress->setValue(static_cast<int>(fraction * 1000));
  });
  QObject::connect(jobs, &JobRunner::RunningChanged, this, [this](int running) {
    this->Progress->setVisible(running > 0);
    this->Cancel->setVisible(running > 0);
    if (running == 0)
    {
      this->Progress->setValue(0);
    }
  });
  QObject::connect(this->Cancel, &QPushButton::clicked, this, [this]() {
    this->Doc->CancelAll();
    this->ShowMessage("Cancelled: the items keep their last results and the settings they were "
                      "computed with");
  });
}

// The menus and the pipeline toolbar, menu by menu (each a named step).
void StudioMainWindow::BuildMenus()
{
  this->BuildFileMenu();
  this->BuildEditMenu();
  QToolBar* tools = this->BuildPipelineMenu();
  this->BuildViewMenu(tools);
  AddHelpMenu(this, DataDirectory());
}

// File: open, recent files, save, examples, export, quit.
void StudioMainWindow::BuildFileMenu()
{
  QMenu* file = this->menuBar()->addMenu("&File");
  file->addAction(this->style()->standardIcon(QStyle::SP_DialogOpenButton), "&Open...", this,
    [this]() {
      if (!this->MaySetDocumentAside())
      {
        return;
      }
      const QString path = this->AskOpenPath("Open Project, Metric or Scene", "JSON (*.json);;All files (*)");
      if (!path.isEmpty())
      {
        this->OpenFile(path);
      }
    }, QKeySequence::Open);
  this->BuildRecentFilesMenu(file);
  // Save and say so in the status bar (nothing when the dialog was cancelled).
  const auto saveProjectTo = [this](const QString& path) {
    if (!path.isEmpty())
    {
      const QString error = this->SaveProject(path);
      this->ShowMessage(error.isEmpty() ? "Project saved to " + path : error, !error.isEmpty());
    }
  };
  file->addAction("&Save Project", this, [this, saveProjectTo]() {
    saveProjectTo(this->Project.Path().isEmpty()
      ? this->AskSavePath("Save Project", "Riemann Studio project (*.json)", "json")
      : this->Project.Path());
  }, QKeySequence::Save);
  QAction* saveAs = file->addAction("Save Project &As...", this, [this, saveProjectTo]() {
    saveProjectTo(this->AskSavePath("Save Project As", "Riemann Studio project (*.json)", "json"));
  });
  // QKeySequence::SaveAs is empty on platforms without a theme (Xvfb): say it.
  QList<QKeySequence> saveAsKeys = QKeySequence::keyBindings(QKeySequence::SaveAs);
  if (!saveAsKeys.contains(QKeySequence(QStringLiteral("Ctrl+Shift+S"))))
  {
    saveAsKeys.prepend(QKeySequence(QStringLiteral("Ctrl+Shift+S")));
  }
  saveAs->setShortcuts(saveAsKeys);
  file->addAction("Save &Metric As...", this, [this]() {
    const QString path = this->AskSavePath("Save Metric (with the slider values)", "Metric (*.json)", "json");
    if (!path.isEmpty())
    {
      const QString error = this->SaveMetric(path);
      this->ShowMessage(error.isEmpty() ? "Metric saved to " + path : error, !error.isEmpty());
    }
  });
  this->BuildExamplesMenu(file);
  this->BuildExportMenu(file);
  file->addSeparator();
  file->addAction("&Quit", this, &QWidget::close, QKeySequence::Quit);
}

// Open Recent: filled when it opens (the list lives in the settings, shared by windows).
void StudioMainWindow::BuildRecentFilesMenu(QMenu* file)
{
  QMenu* recent = file->addMenu("Open &Recent");
  recent->setObjectName("RecentFilesMenu");
  QObject::connect(recent, &QMenu::aboutToShow, this, [this, recent]() {
    recent->clear();
    const QStringList paths = ProjectSession::RecentFiles();
    for (int i = 0; i < paths.size(); ++i)
    {
      const QString path = paths[i];
      recent->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()), this,
        [this, path]() {
          if (this->MaySetDocumentAside())
          {
            this->OpenFile(path);
          }
        })->setToolTip(path);
    }
    if (paths.isEmpty())
    {
      recent->addAction("(none)")->setEnabled(false);
    }
  });
}

// Examples: the shipped projects, metrics and scenes.
void StudioMainWindow::BuildExamplesMenu(QMenu* file)
{
  QMenu* examples = file->addMenu("&Examples");
  examples->setObjectName("ExamplesMenu");
  for (const QString& folder : { QStringLiteral("studio"), QStringLiteral("metrics"), QStringLiteral("scenes") })
  {
    QMenu* menu = examples->addMenu(folder == "studio" ? "Projects" : folder == "metrics" ? "Metrics" : "Scenes");
    const QDir directory(DataDirectory() + "/" + folder);
    for (const QFileInfo& entry : directory.entryInfoList({ "*.json" }, QDir::Files, QDir::Name))
    {
      const QString path = entry.absoluteFilePath();
      menu->addAction(entry.completeBaseName(), this, [this, path]() {
        if (this->MaySetDocumentAside())
        {
          this->OpenFile(path);
        }
      });
    }
  }
}

// Export: the selected item's data, pictures and films, the Python script.
void StudioMainWindow::BuildExportMenu(QMenu* file)
{
  QMenu* exports = file->addMenu("E&xport");
  exports->addAction("Selected Item's &Data...", this, [this]() {
    PipelineItem* item = this->BrowserWidget->SelectedItem();
    if (!item)
    {
      this->ShowMessage("Select an item in the pipeline browser first", true);
      return;
    }
    const bool image = item->Kind() == "field";
    const QString path = this->AskSavePath("Export " + item->Name(),
      (image ? QStringLiteral("VTK image data (*.vti)") : QStringLiteral("VTK poly data (*.vtp)")) +
        ";;CSV table of the points (*.csv)",
      image ? "vti" : "vtp");
    if (!path.isEmpty())
    {
      const QString error = this->ExportItemData(item, path);
      this->ShowMessage(error.isEmpty() ? item->Name() + " written to " + path : error, !error.isEmpty());
    }
  });
  // Pictures and films at the size asked for, of the view(s) chosen.
  exports->addAction("&Screenshot...", this, &StudioMainWindow::AskSaveScreenshot,
    QKeySequence(Qt::CTRL | Qt::Key_P));
  exports->addAction("&Animation...", this, &StudioMainWindow::AskExportAnimation,
    QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
  exports->addAction("Screenshot of the &Window...", this, [this]() {
    const QString path = this->AskSavePath("Save Screenshot", "PNG image (*.png)", "png");
    if (!path.isEmpty())
    {
      const QString error = this->SaveScreenshot(path, WindowShot);
      this->ShowMessage(error.isEmpty() ? "Screenshot saved to " + path : error, !error.isEmpty());
    }
  });
  exports->addAction("&Python Script...", this, [this]() {
    const QString path = this->AskSavePath("Export Python Script", "Python (*.py)", "py");
    if (!path.isEmpty())
    {
      const QString error = this->ExportPythonScript(path);
      this->ShowMessage(error.isEmpty() ? "Python script written to " + path : error, !error.isEmpty());
    }
  });
  exports->addAction(this->TimeWidget->ExportAction());
}

void StudioMainWindow::BuildEditMenu()
{
  // Edit: undo and redo, named by the change ("Undo Add Geodesics").
  QMenu* edit = this->menuBar()->addMenu("&Edit");
  edit->setObjectName("EditMenu");
  QAction* undo = this->History->Stack()->createUndoAction(this, "&Undo");
  undo->setShortcuts(QKeySequence::Undo);
  QAction* redo = this->History->Stack()->createRedoAction(this, "&Redo");
  QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
  for (const char* key : { "Ctrl+Shift+Z", "Ctrl+Y" })
  {
    if (!redoKeys.contains(QKeySequence(key)))
    {
      redoKeys << QKeySequence(key);
    }
  }
  redo->setShortcuts(redoKeys);
  edit->addAction(undo);
  edit->addAction(redo);
}

QToolBar* StudioMainWindow::BuildPipelineMenu()
{
  // Pipeline: add items (menu and toolbar), delete.
  QMenu* pipeline = this->menuBar()->addMenu("&Pipeline");
  QToolBar* tools = this->addToolBar("Pipeline");
  tools->setObjectName("PipelineToolBar");
  for (const std::string& kind : PipelineItemKinds())
  {
    QAction* add = pipeline->addAction(PipelineItemAction(kind), this,
      [this, kind]() { this->Doc->AddItem(kind); });
    add->setObjectName(QString::fromStdString("Add:" + kind));
    tools->addAction(add);
  }
  pipeline->addSeparator();
  pipeline->addAction("&Delete Selected Item", this, [this]() {
    if (PipelineItem* item = this->BrowserWidget->SelectedItem())
    {
      this->Doc->RemoveItem(item);
    }
  });
  tools->addSeparator();
  return tools;
}

void StudioMainWindow::BuildViewMenu(QToolBar* tools)
{
  // View: layout, cameras, picking, backend.
  QMenu* view = this->menuBar()->addMenu("&View");
  QAction* sheet = this->SheetDock->toggleViewAction();
  sheet->setText("Spread&sheet (the selected item's points)");
  view->addAction(sheet);
  QAction* shell = this->ShellDock->toggleViewAction();
  shell->setText("&Python Shell");
  shell->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
  view->addAction(shell);
  view->addAction("Both Views &Side by Side", this, [this]() { this->SetViewLayout(BothViews); });
  view->addAction("&Inside View Only", this, [this]() { this->SetViewLayout(InsideOnly); });
  view->addAction("&Outside View Only", this, [this]() { this->SetViewLayout(OutsideOnly); });
  view->addSeparator();
  QAction* resetInside = view->addAction("Reset &Observer (the scene's camera)", this,
    [this]() { this->Doc->ResetObserver(); });
  QAction* resetOutside = view->addAction("Reset Outside &Camera", this, [this]() {
    this->OutsideWidget->ResetCamera();
    this->OutsideWidget->RenderNow();
  });
  this->PickAction = view->addAction("&Pick Rays (click a pixel of the inside view)");
  this->PickAction->setCheckable(true);
  this->PickAction->setToolTip("Click a pixel of the inside view to see its ray in the outside "
                               "view (Ctrl+click always picks)");
  QObject::connect(this->PickAction, &QAction::toggled, this,
    [this](bool on) { this->InsideWidget->SetPickMode(on); });
  tools->addAction(resetInside);
  tools->addAction(resetOutside);
  tools->addAction(this->PickAction);
}

void StudioMainWindow::ShowSpreadsheet()
{
  if (!this->SheetDock || !this->SheetDock->isVisible())
  {
    return; // filled when shown
  }
  if (PipelineItem* item = this->BrowserWidget->SelectedItem())
  {
    this->SheetWidget->Show(item->Name(), item->Result(0));
  }
  else if (this->Picked->GetNumberOfPoints() > 0)
  {
    this->SheetWidget->Show(QStringLiteral("Picked ray"), this->Picked);
  }
  else
  {
    this->SheetWidget->Show(QString(), nullptr);
  }
}

void StudioMainWindow::UpdateKeyHandles()
{
  // A selected spline camera path's keys are handles in the outside view;
  // a drag applies them as the properties panel would (one undo step).
  PipelineItem* item = this->BrowserWidget->SelectedItem();
  OutsideView::Keys keys;
  if (item && item->Kind() == "camera-path" && item->Settings().at("PathType") == "spline")
  {
    for (const nlohmann::json& key : item->Settings().at("KeyPositions"))
    {
      keys.push_back({ key[0].get<double>(), key[1].get<double>(), key[2].get<double>() });
    }
  }
  if (keys.empty())
  {
    this->OutsideWidget->EditKeys({}, nullptr);
    return;
  }
  this->OutsideWidget->EditKeys(keys, [this, item](const OutsideView::Keys& moved) {
    nlohmann::json positions = nlohmann::json::array();
    for (const auto& key : moved)
    {
      positions.push_back({ key[0], key[1], key[2] });
    }
    const QString error = item->ApplySettings({ { "KeyPositions", positions } });
    if (!error.isEmpty())
    {
      this->ShowMessage(item->Name() + ": " + error, true);
    }
    this->ShowSelection();
  });
}

void StudioMainWindow::ShowSelection()
{
  this->ShowSpreadsheet();
  this->UpdateKeyHandles();
  if (PipelineItem* item = this->BrowserWidget->SelectedItem())
  {
    this->PropertiesWidget->Show(
      QStringLiteral("<b>%1</b> (%2)").arg(item->Name(), QString::fromStdString(item->FilterClass())),
      item->Properties(), item->Settings(),
      [item](const nlohmann::json& settings) { return item->ApplySettings(settings); });
  }
  else if (this->BrowserWidget->IsSceneSelected())
  {
    this->ShowInsideViewSettings();
  }
  else
  {
    this->PropertiesWidget->Clear(QStringLiteral(
      "<b>Metric</b>: %1<br>Edit it in the Metric panel; its parameters get sliders there.")
                                    .arg(QString::fromStdString(this->Doc->Metric()->GetDescription())
                                           .toHtmlEscaped()));
  }
}

void StudioMainWindow::ShowInsideViewSettings()
{
  // The observer's camera, the samples and the renderer (the declared
  // picture settings' fields: PictureValues.h), the choice of the scene's integrator,
  // then the integration settings of the rays (declared, IntegrationValues.h).
  std::vector<PropertySpec> specs = PicturePropertySpecs();
  PropertySpec sceneSettings;
  sceneSettings.Key = "UseSceneSettings";
  sceneSettings.Label = "Scene's integrator";
  sceneSettings.Type = PropertySpec::Boolean;
  sceneSettings.Help = "Use the scene's \"integrator\" block (else the settings below)";
  specs.push_back(sceneSettings);
  for (const PropertySpec& spec : IntegrationPropertySpecs())
  {
    specs.push_back(spec);
  }
  const std::string samplesKey = "SamplesPerPixel";
  const std::string backendKey = "Backend";
  nlohmann::json values = CameraValues(this->Doc->Observer());
  values[backendKey] = this->InsideWidget->GetBackend() == InsideView::GPU ? "gpu" : "cpu";
  values[samplesKey] = this->InsideWidget->GetSamplesPerPixel();
  values["UseSceneSettings"] = this->Doc->UseSceneSettings();
  values.update(IntegrationValues(this->Doc->RaySettings()));
  this->PropertiesWidget->Show("<b>Inside view</b> (the observer and the scene's rays)", specs,
    values,
    [this, samplesKey, backendKey](const nlohmann::json& changes)
    {
      // The camera first: a camera that defines no view refuses the whole
      // edit, before anything else is applied.
      nlohmann::json camera = nlohmann::json::object();
      for (const auto& entry : changes.items())
      {
        if (vtkRiemannPictureSettings::IsCameraSetting(entry.key()))
        {
          camera[entry.key()] = entry.value();
        }
      }
      if (!camera.empty())
      {
        const std::string refused = ApplyCameraValues(camera, this->Doc->Observer());
        if (!refused.empty())
        {
          return QString::fromStdString(refused);
        }
      }
      nlohmann::json integration = nlohmann::json::object();
      for (const auto& entry : changes.items())
      {
        if (vtkRiemannPictureSettings::IsCameraSetting(entry.key()))
        {
          continue;
        }
        if (entry.key() == backendKey)
        {
          this->InsideWidget->SetBackend(entry.value() == "cpu" ? InsideView::CPU : InsideView::GPU);
        }
        else if (entry.key() == samplesKey)
        {
          this->InsideWidget->SetSamplesPerPixel(entry.value().get<int>());
        }
        else if (entry.key() == "UseSceneSettings")
        {
          this->Doc->SetUseSceneSettings(entry.value().get<bool>());
        }
        else
        {
          integration[entry.key()] = entry.value();
        }
      }
      // The integration settings (IntegrationValues.h).
      ApplyIntegrationValues(integration, this->Doc->RaySettings());
      this->InsideWidget->RenderNow();
      this->Doc->ObserverChanged(); // ray bundles follow the new settings
      return QString();
    });
}

void StudioMainWindow::PlacePoint(double x, double y, double z)
{
  PipelineItem* item = this->BrowserWidget->SelectedItem();
  const double point[3] = { x, y, z };
  if (!item || !item->TakePickedPoint(point))
  {
    if (!item && this->Picked->GetNumberOfPoints() > 0)
    {
      this->MeasureOnPickedRay(point);
      return;
    }
    this->ShowMessage(QStringLiteral("Ctrl+click places the points of a Connection (From, then "
                                     "To) or a Distance Field (its seed): select one first; "
                                     "with nothing selected, two points on the picked ray "
                                     "measure its arc length"),
      false);
    return;
  }
  this->ShowMessage(QStringLiteral("%1: point (%2, %3, %4)")
                      .arg(item->Name())
                      .arg(x, 0, 'g', 4)
                      .arg(y, 0, 'g', 4)
                      .arg(z, 0, 'g', 4),
    false);
  this->ShowSelection(); // the form shows the new point
}

void StudioMainWindow::MeasureOnPickedRay(const double point[3])
{
  // Ctrl+click twice: the ray's points nearest to each click, and the arc
  // length the ray travelled between them.
  const vtkIdType nearest = NearestRayPoint(this->Picked, point);
  if (this->MeasureStart < 0)
  {
    this->MeasureStart = nearest;
    this->Measured = std::numeric_limits<double>::quiet_NaN();
    this->ShowMessage(QStringLiteral("Measuring on the picked ray: from its point %1; Ctrl+click "
                                     "the second point")
                        .arg(nearest));
    return;
  }
  this->Measured = ArcLengthBetween(this->Picked, this->MeasureStart, nearest);
  this->ShowMessage(QStringLiteral("Arc length along the picked ray from its point %1 to %2: %3")
                      .arg(this->MeasureStart)
                      .arg(nearest)
                      .arg(this->Measured, 0, 'g', 6));
  this->MeasureStart = -1;
}

void StudioMainWindow::PickPixel(int column, int row)
{
  int width, height;
  this->InsideWidget->PixelSize(width, height);
  if (column < 0 || row < 0 || column >= width || row >= height)
  {
    return;
  }
  // The same rays the inside view draws: vtkRiemannRayBundle for one pixel.
  vtkNew<vtkRiemannRayBundle> bundle;
  SetUpInsideViewRays(bundle.Get(), this->Doc->MakeJobInputs(), width, height, false);
  bundle->SetPixelRegion(column, column, row, row);
  bundle->UsePixelRegionOn();
  bundle->Update();
  vtkPolyData* ray = bundle->GetOutput();
  if (ray->GetNumberOfCells() != 1)
  {
    this->ShowMessage(QStringLiteral("Pixel (%1, %2): no ray (%3)")
                        .arg(column)
                        .arg(row)
                        .arg(QString::fromUtf8(bundle->GetLastError())),
      true);
    return;
  }
  this->Picked->DeepCopy(ray);
  this->MeasureStart = -1; // a new ray: a new measure
  this->OutsideWidget->ShowPickedRay(this->Picked);
  this->ShowSpreadsheet();
  vtkCellData* cells = ray->GetCellData();
  const double length = cells->GetArray("Length")->GetTuple1(0);
  const int reason = static_cast<int>(cells->GetArray("ReasonForTermination")->GetTuple1(0));
  double end[3];
  ray->GetPoint(ray->GetNumberOfPoints() - 1, end);
  this->ShowMessage(QStringLiteral("Pixel (%1, %2): ray ends at (%3, %4, %5) after length %6: %7")
                      .arg(column)
                      .arg(row)
                      .arg(end[0], 0, 'f', 3)
                      .arg(end[1], 0, 'f', 3)
                      .arg(end[2], 0, 'f', 3)
                      .arg(length, 0, 'f', 3)
                      .arg(ReasonName(reason)));
}

void StudioMainWindow::ShowMessage(const QString& message, bool error)
{
  this->Message->setText(message);
  this->Message->setStyleSheet(error ? QStringLiteral("color: #b00020") : QString());
}

QString StudioMainWindow::StatusText() const
{
  return this->Message->text();
}

QString StudioMainWindow::FrameTimeText() const
{
  return this->FrameTime->text();
}

QString StudioMainWindow::OpenFile(const QString& path, bool showDialog)
{
  QString error;
  bool restoredOutsideCamera = false;
  const QString text = ReadText(path, error);
  const std::string utf8 = text.toStdString();
  if (error.isEmpty())
  {
    if (LooksLikeProject(utf8))
    {
      try
      {
        const ProjectData project =
          ParseProject(utf8, QFileInfo(path).absolutePath().toStdString());
        error = ApplyProject(project, *this->Doc);
        if (error.isEmpty())
        {
          this->EditorWidget->SetText(QString::fromStdString(this->Doc->MetricText()));
          this->InsideWidget->SetBackend(project.Backend == "cpu" ? InsideView::CPU : InsideView::GPU);
          this->InsideWidget->SetSamplesPerPixel(project.Samples);
          this->SetViewLayout(project.Views == "inside" ? InsideOnly
              : project.Views == "outside"             ? OutsideOnly
                                                       : BothViews);
          if (project.HasOutsideCamera)
          {
            project.OutsideCamera.To(this->OutsideWidget->Renderer()->GetActiveCamera());
            this->OutsideWidget->Renderer()->ResetCameraClippingRange();
            restoredOutsideCamera = true;
          }
          this->Project.SetPath(path);
        }
      }
      catch (const ProjectError& e)
      {
        error = e.what();
      }
    }
    else
    {
      const nlohmann::json root = nlohmann::json::parse(utf8, nullptr, false);
      const bool scene = root.is_object() &&
        (root.contains("objects") || root.contains("camera") || root.contains("metric"));
      if (scene)
      {
        error = this->Doc->LoadSceneFile(path);
        if (error.isEmpty())
        {
          this->EditorWidget->SetText(QString::fromStdString(this->Doc->MetricText()));
        }
      }
      else
      {
        // A metric: checked before the editor shows it, so a bad file is
        // refused and the editor keeps its text.
        const std::string folder = QFileInfo(path).absolutePath().toStdString();
        vtkNew<vtkRiemannMetric> check;
        if (!check->SetDefinition(utf8.c_str(), folder.c_str()))
        {
          const TextLocation where = check->GetLastErrorPlace().Text;
          error = (where.Known ? QString::fromStdString(DescribeTextPlace(where)) + ": " : QString()) +
            QString::fromUtf8(check->GetLastError());
        }
        else
        {
          this->Doc->SetMetricDirectory(folder);
          this->EditorWidget->SetText(text);
        }
      }
    }
  }
  if (!error.isEmpty())
  {
    if (!error.startsWith(path))
    {
      error = path + ": " + error;
    }
    this->ShowMessage(error, true);
    if (showDialog)
    {
      QMessageBox::warning(this, "Cannot open " + QFileInfo(path).fileName(),
        error + "\n\nNothing was changed.");
    }
    return error;
  }
  this->ShowMessage("Opened " + path);
  this->History->Reset(); // a new document: undo does not go back into the old one
  this->RememberFile(path);
  this->UpdateTitle();
  if (!restoredOutsideCamera)
  {
    this->OutsideWidget->ResetCamera();
  }
  this->OutsideWidget->ScheduleRender();
  return QString();
}

QString StudioMainWindow::SaveProject(const QString& path)
{
  ProjectData project = CaptureProject(*this->Doc);
  project.Backend = this->InsideWidget->GetBackend() == InsideView::CPU ? "cpu" : "gpu";
  project.Samples = this->InsideWidget->GetSamplesPerPixel();
  project.Views = this->CurrentLayout == InsideOnly ? "inside"
    : this->CurrentLayout == OutsideOnly            ? "outside"
                                                    : "both";
  project.HasOutsideCamera = true;
  project.OutsideCamera.From(this->OutsideWidget->Renderer()->GetActiveCamera());
  const std::string text =
    ProjectToJson(project, QFileInfo(path).absolutePath().toStdString()).dump(2) + "\n";
  const QString error = WriteFileAtomically(path, QByteArray::fromStdString(text));
  if (error.isEmpty())
  {
    this->Project.SetPath(path);
    this->RememberFile(path);
    this->UpdateTitle();
  }
  return error;
}

QString StudioMainWindow::SaveMetric(const QString& path)
{
  return WriteFileAtomically(path, QByteArray::fromStdString(this->Doc->EffectiveMetricText()));
}

QString StudioMainWindow::ExportPythonScript(const QString& path)
{
  return WriteFileAtomically(path, QByteArray::fromStdString(PythonScript(*this->Doc)));
}

QString StudioMainWindow::ExportItemData(PipelineItem* item, const QString& path)
{
  if (!item->Result(0))
  {
    return item->Name() + ": nothing to export yet (its job has not finished)";
  }
  const QFileInfo info(path);
  if (info.suffix().toLower() == "csv")
  {
    // The points as the spreadsheet shows them; other outputs next to it.
    for (int port = 0; port < item->NumberOfResults(); ++port)
    {
      const QString target = port == 0
        ? path
        : info.dir().filePath(info.completeBaseName() + QStringLiteral("-%1.csv").arg(port));
      const QString error = WriteFileAtomically(target, TableCsv(PointTable(item->Result(port))));
      if (!error.isEmpty())
      {
        return error;
      }
    }
    return QString();
  }
  for (int port = 0; port < item->NumberOfResults(); ++port)
  {
    vtkDataObject* data = item->Result(port);
    const bool image = vtkImageData::SafeDownCast(data) != nullptr;
    // Port 0 at the path given; other ports next to it (name-1.vtp, ...).
    const QString target = port == 0
      ? path
      : info.dir().filePath(info.completeBaseName() + QStringLiteral("-%1.").arg(port) + (image ? "vti" : "vtp"));
    // Whole or not at all: write a temporary file next to it, then rename.
    const QString temporary = target + ".part";
    vtkSmartPointer<vtkXMLWriter> writer;
    if (image)
    {
      writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
    }
    else
    {
      writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    }
    writer->SetInputDataObject(data);
    writer->SetFileName(temporary.toLocal8Bit().constData());
    if (!writer->Write())
    {
      QFile::remove(temporary);
      return target + ": cannot write the file";
    }
    QFile::remove(target);
    if (!QFile::rename(temporary, target))
    {
      QFile::remove(temporary);
      return target + ": cannot replace the file";
    }
  }
  return QString();
}

void StudioMainWindow::SetPictureSize(Shot what, int width, int height)
{
  // Widget sizes are in device-independent pixels; pictures in device pixels.
  const qreal ratio = this->devicePixelRatioF();
  const auto fix = [ratio](QWidget* view, int w, int h) {
    view->setFixedSize(static_cast<int>(std::lround(w / ratio)), static_cast<int>(std::lround(h / ratio)));
  };
  switch (what)
  {
    case InsideShot:
      this->SetViewLayout(InsideOnly);
      fix(this->InsideWidget, width, height);
      break;
    case OutsideShot:
      this->SetViewLayout(OutsideOnly);
      fix(this->OutsideWidget, width, height);
      break;
    case BothShot:
      this->SetViewLayout(BothViews);
      fix(this->InsideWidget, width / 2, height);
      fix(this->OutsideWidget, width - width / 2, height);
      break;
    case WindowShot:
      this->resize(width, height);
      break;
  }
}

void StudioMainWindow::ReleasePictureSize(Layout layout)
{
  for (QWidget* view : { static_cast<QWidget*>(this->InsideWidget), static_cast<QWidget*>(this->OutsideWidget) })
  {
    view->setMinimumSize(0, 0);
    view->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
  }
  this->SetViewLayout(layout);
}

QImage StudioMainWindow::CapturePicture(Shot what)
{
  QImage image;
  if (what == InsideShot)
  {
    image = this->InsideWidget->Capture();
  }
  else if (what == OutsideShot)
  {
    image = this->OutsideWidget->Capture();
  }
  else if (what == BothShot)
  {
    const QImage inside = this->InsideWidget->Capture();
    const QImage outside = this->OutsideWidget->Capture();
    image = QImage(inside.width() + outside.width(), std::max(inside.height(), outside.height()),
      QImage::Format_RGB32);
    image.fill(Qt::black);
    QPainter painter(&image);
    painter.drawImage(0, 0, inside);
    painter.drawImage(inside.width(), 0, outside);
  }
  else
  {
    // The inside view's still frame finished first (Capture refines it to
    // the end): the window's own grab would show whichever lattice was last.
    this->InsideWidget->Capture();
    QCoreApplication::processEvents();
    image = this->grab().toImage();
  }
  return image;
}

QString StudioMainWindow::SaveScreenshot(const QString& path, Shot what)
{
  const QImage image = this->CapturePicture(what);
  if (image.isNull())
  {
    return "nothing to capture (is the window shown?)";
  }
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, "PNG"))
  {
    return path + ": cannot encode PNG";
  }
  return WriteFileAtomically(path, bytes);
}

void StudioMainWindow::AskExportAnimation()
{
  AnimationDialog dialog(this->Doc, true, this);
  if (dialog.exec() != QDialog::Accepted)
  {
    return;
  }
  const AnimationSettings settings = dialog.Settings();
  QProgressDialog progress("Exporting the animation...", "Cancel", 0, settings.Frames, this);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(0);
  const QString error = ExportAnimation(*this, settings, [&progress](int done, int) {
    progress.setValue(done);
    QCoreApplication::processEvents();
    return !progress.wasCanceled();
  });
  this->ShowMessage(error.isEmpty()
      ? QStringLiteral("%1 frames written to %2").arg(settings.Frames).arg(settings.Output)
      : error == "cancelled" ? QStringLiteral("Export cancelled: nothing written") : error,
    !error.isEmpty() && error != "cancelled");
}

void StudioMainWindow::AskSaveScreenshot()
{
  AnimationDialog dialog(this->Doc, false, this);
  if (dialog.exec() != QDialog::Accepted)
  {
    return;
  }
  const AnimationSettings settings = dialog.Settings();
  const QString error = ExportAnimation(*this, settings);
  this->ShowMessage(error.isEmpty() ? "Screenshot saved to " + settings.Output : error, !error.isEmpty());
}

void StudioMainWindow::SetViewLayout(Layout layout)
{
  this->CurrentLayout = layout;
  this->InsideWidget->setVisible(layout != OutsideOnly);
  this->OutsideWidget->setVisible(layout != InsideOnly);
}

void StudioMainWindow::Settle(int timeoutMilliseconds)
{
  QElapsedTimer timer;
  timer.start();
  do
  {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  } while (this->Doc->Jobs()->NumberOfRunningJobs() > 0 && timer.elapsed() < timeoutMilliseconds);
  QCoreApplication::processEvents();
  if (this->InsideWidget->GetBackend() == InsideView::GPU)
  {
    this->InsideWidget->RenderNow();
  }
  else
  {
    this->InsideWidget->renderWindow()->Render(); // the traced picture, not a new trace
  }
  this->OutsideWidget->RenderNow();
  QCoreApplication::processEvents();
}

QString StudioMainWindow::AskOpenPath(const QString& title, const QString& filter)
{
  const QString path = QFileDialog::getOpenFileName(this, title, this->Project.StartFolder(), filter);
  this->Project.RememberFolderOf(path);
  return path;
}

QString StudioMainWindow::AskSavePath(const QString& title, const QString& filter, const QString& suffix)
{
  QString path = QFileDialog::getSaveFileName(this, title, this->Project.StartFolder(), filter);
  this->Project.RememberFolderOf(path);
  if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty())
  {
    path += "." + suffix;
  }
  return path;
}

void StudioMainWindow::UpdateTitle()
{
  const QString project = this->Project.Path().isEmpty() ? QStringLiteral("untitled")
                                                        : QFileInfo(this->Project.Path()).fileName();
  // "[*]": Qt shows "*" there while the window is modified (UpdateModifiedMark).
  this->setWindowTitle(QStringLiteral("%1[*] - %2 - Riemann Studio")
                         .arg(project, QString::fromStdString(this->Doc->Metric()->GetDescription())));
}

bool StudioMainWindow::IsDocumentModified() const
{
  return this->Project.IsModified(ProjectFingerprint(*this->Doc));
}

void StudioMainWindow::UpdateModifiedMark()
{
  this->setWindowModified(this->Project.IsModified(this->History->Fingerprint()));
}

QUndoStack* StudioMainWindow::UndoStack() const
{
  return this->History->Stack();
}

void StudioMainWindow::RememberFile(const QString& path)
{
  this->Project.MarkClean(ProjectFingerprint(*this->Doc));
  this->Project.RememberFolderOf(path);
  ProjectSession::AddRecentFile(path);
  this->UpdateModifiedMark();
}

bool StudioMainWindow::MaySetDocumentAside()
{
  if (!this->AskToSaveChanges || !this->IsDocumentModified())
  {
    return true;
  }
  const QString name = this->Project.Path().isEmpty() ? QStringLiteral("the untitled project")
                                                      : QFileInfo(this->Project.Path()).fileName();
  QMessageBox question(QMessageBox::Warning, "Unsaved changes",
    "Save the changes to " + name + "?", QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
    this);
  question.setObjectName("UnsavedChangesQuestion");
  question.setDefaultButton(QMessageBox::Save);
  const int answer = question.exec();
  if (answer == QMessageBox::Discard)
  {
    return true;
  }
  if (answer != QMessageBox::Save)
  {
    return false;
  }
  const QString path = this->Project.Path().isEmpty()
    ? this->AskSavePath("Save Project", "Riemann Studio project (*.json)", "json")
    : this->Project.Path();
  if (path.isEmpty())
  {
    return false;
  }
  const QString error = this->SaveProject(path);
  this->ShowMessage(error.isEmpty() ? "Project saved to " + path : error, !error.isEmpty());
  return error.isEmpty();
}

void StudioMainWindow::closeEvent(QCloseEvent* event)
{
  if (!this->MaySetDocumentAside())
  {
    event->ignore();
    return;
  }
  this->Doc->Jobs()->CancelAll();
  this->Doc->Jobs()->WaitForAll();
  event->accept();
}
}
}
