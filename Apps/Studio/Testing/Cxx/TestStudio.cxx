// riemann-studio driven with QtTest: the real window, under xvfb-run.
#include "InsideView.h"
#include "StudioMainWindow.h"

#include "QVTKOpenGLNativeWidget.h"

#include <QtTest/QtTest>

using namespace riemann::studio;

class TestStudio : public QObject
{
  Q_OBJECT
private Q_SLOTS:
  void WindowOpensWithDefaultScene();
};

void TestStudio::WindowOpensWithDefaultScene()
{
  StudioMainWindow window;
  window.resize(1200, 800);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  window.Settle();
  const QImage inside = window.Inside()->Capture();
  QVERIFY(!inside.isNull());
  inside.save("studio-window-inside.png");
  window.grab().save("studio-window.png");
}

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestStudio test;
  return QTest::qExec(&test, argc, argv);
}

#include "TestStudio.moc"
