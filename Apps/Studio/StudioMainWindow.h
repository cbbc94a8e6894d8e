/**
 * @file StudioMainWindow.h
 * @brief Riemann Studio's window, in ParaView's layout: pipeline browser and
 * properties panel on the left, the inside and outside views in the middle,
 * the metric editor with its parameter sliders on the right, the time bar
 * at the bottom and a status bar with progress and Cancel.
 */
#ifndef RiemannStudio_StudioMainWindow_h
#define RiemannStudio_StudioMainWindow_h

#include "DocumentHistory.h"
#include "ProjectSession.h"
#include "SpreadsheetView.h"

#include <QImage>
#include <QMainWindow>

#include <limits>

#include "vtkNew.h"
#include "vtkType.h" // For vtkIdType

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QSplitter;
class QToolBar;
class vtkPolyData;

namespace riemann
{
namespace studio
{
class InsideView;
class MetricEditor;
class OutsideView;
class ParameterPanel;
class PipelineBrowser;
class PipelineItem;
class PropertiesPanel;
class StudioDocument;
class PythonShell;
class TimeBar;

class StudioMainWindow : public QMainWindow
{
  Q_OBJECT
public:
  enum Layout
  {
    BothViews,
    InsideOnly,
    OutsideOnly
  };
  enum Shot
  {
    InsideShot,
    OutsideShot,
    BothShot,
    WindowShot
  };

  explicit StudioMainWindow(QWidget* parent = nullptr);
  ~StudioMainWindow() override;

  ///@{
  /// Open a project, metric or scene file (told apart by their keys). On
  /// failure nothing changes and the message says what and where; with
  /// `showDialog` it is also shown in a dialog.
  QString OpenFile(const QString& path, bool showDialog = true);
  QString SaveProject(const QString& path);
  QString SaveMetric(const QString& path);
  QString ExportPythonScript(const QString& path);
  QString ExportItemData(PipelineItem* item, const QString& path);
  QString SaveScreenshot(const QString& path, Shot what);
  ///@}

  /**
   * Make the picture SaveScreenshot(`what`) takes `width` x `height` pixels:
   * the window's size for WindowShot, else the view's (both views side by
   * side, each half the width, for BothShot), fixed; the window grows
   * around them (the views render into their own framebuffers, so a
   * picture larger than the screen is whole).
   */
  void SetPictureSize(Shot what, int width, int height);
  /// Undo SetPictureSize: the views size with the window again, in `layout`.
  void ReleasePictureSize(Layout layout);
  /// The picture SaveScreenshot(`what`) writes (null when nothing is shown).
  QImage CapturePicture(Shot what);
  void SetViewLayout(Layout layout);
  Layout ViewLayout() const { return this->CurrentLayout; }
  /// Render both views now and let every pending job finish (for --screenshot).
  void Settle(int timeoutMilliseconds = 120000);

  ///@{
  /// Parts of the window (tests, scripting).
  StudioDocument* Document() const { return this->Doc; }
  DocumentHistory* UndoHistory() const { return this->History; }
  InsideView* Inside() const { return this->InsideWidget; }
  OutsideView* Outside() const { return this->OutsideWidget; }
  PipelineBrowser* Browser() const { return this->BrowserWidget; }
  PropertiesPanel* Properties() const { return this->PropertiesWidget; }
  MetricEditor* Editor() const { return this->EditorWidget; }
  ParameterPanel* Parameters() const { return this->ParameterWidget; }
  TimeBar* Time() const { return this->TimeWidget; }
  QPushButton* CancelButton() const { return this->Cancel; }
  SpreadsheetView* Spreadsheet() const { return this->SheetWidget; }
  QDockWidget* SpreadsheetDock() const { return this->SheetDock; }
  QDockWidget* PythonShellDock() const { return this->ShellDock; }
  PythonShell* Shell() const { return this->ShellWidget; }
  ///@}

  /// Pick pixel (column, row) of the inside view: trace its ray, show it.
  void PickPixel(int column, int row);
  /// A point Ctrl+clicked in the outside view: the selected item's to place.
  void PlacePoint(double x, double y, double z);
  /// The last picked ray (vtkRiemannRayBundle's output for that pixel).
  vtkPolyData* PickedRay() const { return this->Picked; }
  /// The last arc length measured on the picked ray (two Ctrl+clicks in the
  /// outside view with no item selected); NaN before one.
  double MeasuredArcLength() const { return this->Measured; }
  /// The status bar's text.
  QString StatusText() const;
  /// The status bar's frame label: "frame N ms", or while the view moves
  /// "moving: 1 ray per d x d pixels".
  QString FrameTimeText() const;
  /// Milliseconds of the last metric change -> inside view drawn.
  double LastUpdateMilliseconds() const { return this->LastUpdate; }

  ///@{
  /// The project file and its state (ProjectSession): whether the document
  /// differs from the file (the title's "*"), and whether closing the
  /// window with unsaved changes asks to save them (default on).
  const ProjectSession& Session() const { return this->Project; }
  /// The undo stack of the document's changes (Edit > Undo, Redo).
  QUndoStack* UndoStack() const;
  bool IsDocumentModified() const;
  void SetAskToSaveChanges(bool ask) { this->AskToSaveChanges = ask; }
  ///@}

protected:
  void closeEvent(QCloseEvent* event) override;

private:
  void BuildDocks();
  void BuildMenus();
  void BuildFileMenu();
  void BuildRecentFilesMenu(QMenu* file);
  void BuildExamplesMenu(QMenu* file);
  void BuildExportMenu(QMenu* file);
  void BuildEditMenu();
  QToolBar* BuildPipelineMenu();
  void BuildViewMenu(QToolBar* tools);
  void BuildStatusBar();
  void ShowSelection();
  /// The selected spline camera path's keys as handles in the outside view.
  void UpdateKeyHandles();
  /// The spreadsheet shows the selected item's points, else the picked ray's.
  void ShowSpreadsheet();
  /// A Ctrl+click with no item selected: one end of a measure on the picked ray.
  void MeasureOnPickedRay(const double point[3]);
  void ShowInsideViewSettings();
  /// File > Export > Animation and Screenshot: the dialog, then the export
  /// (AnimationExport.h) with progress and Cancel.
  void AskExportAnimation();
  void AskSaveScreenshot();
  void ShowMessage(const QString& message, bool error = false);
  QString AskOpenPath(const QString& title, const QString& filter);
  QString AskSavePath(const QString& title, const QString& filter, const QString& suffix);
  void UpdateTitle();
  /// The title's modified mark, from the history's last comparison (DocumentHistory::Compared).
  void UpdateModifiedMark();
  /// The document is the file's now (opened or saved): clean, and a recent file.
  void RememberFile(const QString& path);
  /// Ask whether to save unsaved changes; false when the user cancels.
  bool MaySetDocumentAside();

  StudioDocument* Doc;
  InsideView* InsideWidget;
  OutsideView* OutsideWidget;
  QSplitter* Views;
  PipelineBrowser* BrowserWidget;
  PropertiesPanel* PropertiesWidget;
  MetricEditor* EditorWidget;
  ParameterPanel* ParameterWidget;
  TimeBar* TimeWidget;
  SpreadsheetView* SheetWidget = nullptr;
  QDockWidget* SheetDock = nullptr;
  QDockWidget* ShellDock = nullptr;
  PythonShell* ShellWidget = nullptr;
  QLabel* Message;
  QLabel* FrameTime;
  /// "frame N ms" of the last still frame (shown again when moving stops).
  QString LastFrameTime;
  /// Pixels per ray of the last drawn inside view, along a side.
  double LastDistance = 1.0;
  QProgressBar* Progress;
  QPushButton* Cancel;
  QAction* PickAction = nullptr;
  Layout CurrentLayout = BothViews;
  ProjectSession Project;
  DocumentHistory* History = nullptr;
  bool AskToSaveChanges = true;
  vtkNew<vtkPolyData> Picked;
  /// The first end of a measure on the picked ray (-1: none yet), and the last result.
  vtkIdType MeasureStart = -1;
  double Measured = std::numeric_limits<double>::quiet_NaN();
  double LastUpdate = 0.0;
};
}
}

#endif
