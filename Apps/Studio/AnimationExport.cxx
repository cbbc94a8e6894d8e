#include "AnimationExport.h"

#include "DocumentHistory.h"
#include "InsideView.h"
#include "PipelineItems.h"
#include "ProjectFile.h"
#include "RiemannFilmWriter.h"
#include "StudioDocument.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRiemannCameraPath.h"
#include "vtkRiemannMetric.h"

#include <QBuffer>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include <memory>

namespace riemann
{
namespace studio
{
namespace
{
bool IsFilm(const QString& output)
{
  return FilmWriter::IsFilmPath(output.toStdString());
}

/// Step 1: what is asked makes sense, before anything moves.
QString CheckSettings(const AnimationSettings& settings)
{
  const QString suffix = QFileInfo(settings.Output).suffix().toLower();
  if (suffix != "png" && suffix != "ogv")
  {
    return settings.Output + ": an animation is written as numbered .png pictures or one .ogv film";
  }
  if (settings.Frames < 1 || settings.Frames > 100000)
  {
    return QStringLiteral("an animation has 1 to 100000 frames, not %1").arg(settings.Frames);
  }
  if (settings.Width < 2 || settings.Height < 2 || settings.Width > 8192 || settings.Height > 8192)
  {
    return QStringLiteral("a picture is 2 to 8192 pixels a side, not %1x%2")
      .arg(settings.Width)
      .arg(settings.Height);
  }
  if (suffix == "ogv" && (settings.Width % 2 || settings.Height % 2))
  {
    return QStringLiteral("a film's frames need even sides, not %1x%2")
      .arg(settings.Width)
      .arg(settings.Height);
  }
  return QString();
}

/// Step 2: the observer's flight, from the camera path item named
/// `name`, in the metric at the first frame's t (null without a path).
vtkSmartPointer<vtkPolyData> Flight(
  StudioDocument* document, const AnimationSettings& settings, QString& error)
{
  if (settings.CameraPath.isEmpty())
  {
    return nullptr;
  }
  const CameraPathItem* item = nullptr;
  for (const auto& candidate : document->Items())
  {
    if (candidate->Name() == settings.CameraPath)
    {
      item = dynamic_cast<const CameraPathItem*>(candidate.get());
    }
  }
  if (!item)
  {
    error = "no camera path item named \"" + settings.CameraPath + "\"";
    return nullptr;
  }
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(document->Metric());
  if (settings.AnimateTime && !metric->SetTime(settings.TimeFrom))
  {
    error = QString::fromStdString(metric->GetLastError());
    return nullptr;
  }
  vtkNew<vtkRiemannCameraPath> path;
  path->SetMetric(metric);
  item->Configure(path);
  path->SetNumberOfFrames(settings.Frames);
  path->Update();
  if (*path->GetLastError())
  {
    error = settings.CameraPath + ": " + path->GetLastError();
    return nullptr;
  }
  return path->GetOutput();
}

/// What an export changes and puts back: t, the observer, the layout, and
/// the history's recording.
class PutBack
{
public:
  explicit PutBack(StudioMainWindow& window)
    : Window(window)
    , Time(window.Document()->Time())
    , Layout(window.ViewLayout())
  {
    this->Observer->DeepCopy(window.Document()->Observer());
    window.UndoHistory()->SetPaused(true);
  }
  ~PutBack()
  {
    StudioDocument* document = this->Window.Document();
    document->SetTime(this->Time);
    document->Observer()->DeepCopy(this->Observer);
    document->ObserverChanged();
    this->Window.ReleasePictureSize(this->Layout);
    this->Window.Settle();
    this->Window.UndoHistory()->SetPaused(false);
  }

private:
  StudioMainWindow& Window;
  double Time;
  StudioMainWindow::Layout Layout;
  vtkNew<vtkCamera> Observer;
};

QString WritePng(const QImage& picture, const QString& path)
{
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (!picture.save(&buffer, "PNG"))
  {
    return path + ": cannot encode PNG";
  }
  return WriteFileAtomically(path, bytes);
}
} // namespace

QString ExportAnimation(StudioMainWindow& window, const AnimationSettings& settings,
  const std::function<bool(int, int)>& progress)
{
  QString error = CheckSettings(settings);
  StudioDocument* document = window.Document();
  const vtkSmartPointer<vtkPolyData> flight = error.isEmpty() ? Flight(document, settings, error) : nullptr;
  if (!error.isEmpty())
  {
    return error;
  }
  // Step 3: frame by frame, t and the observer set, the view(s) captured
  // at the picture's size, to the film or the numbered pictures.
  PutBack putBack(window);
  window.SetPictureSize(settings.View, settings.Width, settings.Height);
  std::unique_ptr<FilmWriter> film;
  QStringList written;
  const int frames = settings.Frames;
  for (int k = 0; k < frames && error.isEmpty(); ++k)
  {
    if (settings.AnimateTime)
    {
      const double t = frames > 1
        ? settings.TimeFrom + (settings.TimeTo - settings.TimeFrom) * k / (frames - 1)
        : settings.TimeFrom;
      const MetricStatus status = document->SetTime(t);
      if (!status.Ok())
      {
        error = QStringLiteral("frame %1: %2").arg(k + 1).arg(status.Message);
        break;
      }
    }
    if (flight)
    {
      vtkRiemannCameraPath::ApplyFrame(flight, k, document->Observer());
      document->ObserverChanged();
    }
    window.Settle();
    const QImage picture = window.CapturePicture(settings.View)
                             .scaled(settings.Width, settings.Height)
                             .convertToFormat(QImage::Format_RGB888);
    try
    {
      if (IsFilm(settings.Output))
      {
        if (!film)
        {
          film.reset(new FilmWriter(settings.Output.toStdString(), picture.width(), picture.height()));
        }
        // Rows of a QImage may be padded: the film takes them packed.
        QByteArray rows;
        for (int row = 0; row < picture.height(); ++row)
        {
          rows.append(reinterpret_cast<const char*>(picture.constScanLine(row)), picture.width() * 3);
        }
        film->AddFrame(reinterpret_cast<const unsigned char*>(rows.constData()), picture.width(),
          picture.height());
      }
      else
      {
        const QString path = frames > 1
          ? QString::fromStdString(FramePath(settings.Output.toStdString(), k))
          : settings.Output;
        error = WritePng(picture, path);
        written << path;
      }
    }
    catch (const FilmWriterError& e)
    {
      error = QString::fromStdString(e.what());
    }
    if (error.isEmpty() && progress && !progress(k + 1, frames))
    {
      error = QStringLiteral("cancelled");
    }
  }
  try
  {
    if (film && error.isEmpty())
    {
      film->Close();
    }
  }
  catch (const FilmWriterError& e)
  {
    error = QString::fromStdString(e.what());
  }
  // A cancelled or failed export leaves nothing: the film's partial file
  // goes with its writer, the pictures here.
  if (!error.isEmpty())
  {
    for (const QString& path : written)
    {
      QFile::remove(path);
    }
  }
  return error;
}

AnimationDialog::AnimationDialog(StudioDocument* document, bool animation, QWidget* parent)
  : QDialog(parent)
  , Animation(animation)
{
  this->setWindowTitle(animation ? "Export Animation" : "Save Screenshot");
  auto* form = new QFormLayout(this);
  this->View = new QComboBox(this);
  this->View->setObjectName("AnimationView");
  this->View->addItems({ "Inside view", "Outside view", "Both views" });
  form->addRow("View", this->View);
  auto* size = new QHBoxLayout;
  this->Width = new QSpinBox(this);
  this->Width->setObjectName("AnimationWidth");
  this->Width->setRange(2, 8192);
  this->Width->setValue(640);
  this->Height = new QSpinBox(this);
  this->Height->setObjectName("AnimationHeight");
  this->Height->setRange(2, 8192);
  this->Height->setValue(480);
  size->addWidget(this->Width);
  size->addWidget(this->Height);
  form->addRow("Size (pixels)", size);
  if (animation)
  {
    this->Frames = new QSpinBox(this);
    this->Frames->setObjectName("AnimationFrames");
    this->Frames->setRange(1, 100000);
    this->Frames->setValue(60);
    form->addRow("Frames", this->Frames);
    auto* time = new QHBoxLayout;
    this->AnimateTime = new QCheckBox("t from", this);
    this->AnimateTime->setChecked(true);
    this->TimeFrom = new QDoubleSpinBox(this);
    this->TimeTo = new QDoubleSpinBox(this);
    for (QDoubleSpinBox* box : { this->TimeFrom, this->TimeTo })
    {
      box->setRange(-1e6, 1e6);
      box->setDecimals(4);
    }
    this->TimeTo->setValue(1.0);
    time->addWidget(this->AnimateTime);
    time->addWidget(this->TimeFrom);
    time->addWidget(this->TimeTo);
    form->addRow("Time", time);
    this->CameraPath = new QComboBox(this);
    this->CameraPath->setObjectName("AnimationCameraPath");
    this->CameraPath->addItem("The observer stays");
    for (const auto& item : document->Items())
    {
      if (item->Kind() == "camera-path")
      {
        this->CameraPath->addItem(item->Name());
      }
    }
    this->CameraPath->setToolTip("Fly the observer along a camera path item (Pipeline > Add Camera Path)");
    form->addRow("Camera", this->CameraPath);
  }
  auto* output = new QHBoxLayout;
  this->Output = new QLineEdit(this);
  this->Output->setObjectName("AnimationOutput");
  this->Output->setPlaceholderText(animation ? "film.ogv or frame.png (frame_0000.png, ...)" : "picture.png");
  auto* browse = new QPushButton("Browse...", this);
  QObject::connect(browse, &QPushButton::clicked, this, &AnimationDialog::Browse);
  output->addWidget(this->Output);
  output->addWidget(browse);
  form->addRow("Write to", output);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  QObject::connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

void AnimationDialog::Browse()
{
  const QString filter = this->Animation
    ? QStringLiteral("Ogg Theora film (*.ogv);;Numbered PNG pictures (*.png)")
    : QStringLiteral("PNG picture (*.png)");
  const QString path = QFileDialog::getSaveFileName(this, this->windowTitle(), this->Output->text(), filter);
  if (!path.isEmpty())
  {
    this->Output->setText(path);
  }
}

AnimationSettings AnimationDialog::Settings() const
{
  AnimationSettings settings;
  const StudioMainWindow::Shot views[] = { StudioMainWindow::InsideShot,
    StudioMainWindow::OutsideShot, StudioMainWindow::BothShot };
  settings.View = views[std::max(0, this->View->currentIndex())];
  settings.Width = this->Width->value();
  settings.Height = this->Height->value();
  settings.Output = this->Output->text().trimmed();
  if (this->Animation)
  {
    settings.Frames = this->Frames->value();
    settings.AnimateTime = this->AnimateTime->isChecked();
    settings.TimeFrom = this->TimeFrom->value();
    settings.TimeTo = this->TimeTo->value();
    settings.CameraPath =
      this->CameraPath->currentIndex() > 0 ? this->CameraPath->currentText() : QString();
  }
  else
  {
    settings.Frames = 1;
    settings.AnimateTime = false;
  }
  return settings;
}
}
}
