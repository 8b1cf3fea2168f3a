// ROS-side benchmark harness: an rviz VisualizationManager (as in rviz itself, render panel on the
// X server) with N displays of one class, one per human (human_<i>/robot_description), driven at
// rviz's 30 Hz for a while. Prints one line: class, N, achieved fps, process CPU (% of one core),
// CPU per frame, resident memory at the end and when every human was first drawn. bench/rviz_scaling.py runs it for
// DressedHuman and RobotModel side by side.
//
// Usage: rviz_display_scaling <display class> <count> <seconds> [options]
//   --set <property>=<value>  set a property of every display (repeatable), e.g. Relief=Flat
//   --distance <m>            orbit view distance (default 14)
//   --focal <x;y;z>           orbit view focal point (default 4;4.5;0.9)
//   --view <property>=<value> set a property of the orbit view (repeatable), e.g. Target Frame=body_0
//   --screenshot <path>       save the render window when the measurement starts (<path> with
//                             _start before its extension) and when it ends (<path>)
#include <chrono>
#include <cstdio>
#include <fstream>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include <OgreRenderWindow.h>
#include <QApplication>
#include <ros/ros.h>
#include <rviz/display.h>
#include <rviz/properties/status_property.h>
#include <rviz/render_panel.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>
#include <rviz/visualization_manager.h>

namespace {

// The child property called `name`, or nullptr (subProp() returns a dummy for a missing one).
rviz::Property* childNamed(rviz::Property* parent, const QString& name) {
  for (int c = 0; c < parent->numChildren(); ++c) {
    if (parent->childAt(c)->getName() == name) return parent->childAt(c);
  }
  return nullptr;
}

double residentMegabytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return -1.0;
}

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  const auto program_start = std::chrono::steady_clock::now();
  ros::init(argc, argv, "rviz_display_scaling", ros::init_options::AnonymousName);
  QApplication application(argc, argv);
  const char* usage =
      "usage: rviz_display_scaling <display class> <count> <seconds> [--set property=value]... [--distance m] "
      "[--focal x;y;z] [--view property=value]... [--screenshot path]\n";
  if (argc < 4) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  const QString display_class = argv[1];
  const int count = std::stoi(argv[2]);
  const double seconds = std::stod(argv[3]);
  std::vector<std::pair<QString, QString>> settings, view_settings;
  QString distance = "14.0", focal = "4;4.5;0.9", screenshot;
  for (int i = 4; i < argc; ++i) {
    const std::string option = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "option %s needs a value\n%s", option.c_str(), usage);
      return 2;
    }
    const QString value = argv[++i];
    if (option == "--set" && value.contains('=')) {
      settings.emplace_back(value.section('=', 0, 0), value.section('=', 1));
    } else if (option == "--view" && value.contains('=')) {
      view_settings.emplace_back(value.section('=', 0, 0), value.section('=', 1));
    } else if (option == "--distance") {
      distance = value;
    } else if (option == "--focal") {
      focal = value;
    } else if (option == "--screenshot") {
      screenshot = value;
    } else {
      std::fprintf(stderr, "unknown option or bad value: %s %s\n%s", option.c_str(), argv[i], usage);
      return 2;
    }
  }

  rviz::RenderPanel panel;
  panel.resize(1000, 700);
  panel.show();
  rviz::VisualizationManager manager(&panel);
  panel.initialize(manager.getSceneManager(), &manager);
  manager.initialize();
  manager.setFixedFrame("world");
  std::vector<rviz::Display*> displays;
  for (int i = 0; i < count; ++i) {
    rviz::Display* display = manager.createDisplay(display_class, QString("human %1").arg(i), true);
    displays.push_back(display);
    if (display == nullptr) {
      std::fprintf(stderr, "cannot create a display of class %s\n", argv[1]);
      return 1;
    }
    display->subProp("Robot Description")->setValue(QString("human_%1/robot_description").arg(i));
    for (const auto& setting : settings) {
      rviz::Property* property = childNamed(display, setting.first);
      if (property == nullptr) {
        std::fprintf(stderr, "display %s has no property '%s'\n", argv[1], setting.first.toStdString().c_str());
        return 2;
      }
      property->setValue(setting.second);
    }
  }
  // The view the caller asks for (bench/rviz_scaling.py keeps every human in it).
  rviz::ViewController* view = manager.getViewManager()->getCurrent();
  view->subProp("Distance")->setValue(distance.toDouble());
  view->subProp("Focal Point")->setValue(focal);
  for (const auto& setting : view_settings) {
    rviz::Property* property = childNamed(view, setting.first);
    if (property == nullptr) {
      std::fprintf(stderr, "the view has no property '%s'\n", setting.first.toStdString().c_str());
      return 2;
    }
    property->setValue(setting.second);
  }

  const auto frame = [&] {
    QApplication::processEvents();
    ros::spinOnce();
    QMetaObject::invokeMethod(&manager, "onUpdate", Qt::DirectConnection);
  };
  // Displays that measure themselves (DressedHuman: status "Update", the mean over its last 30
  // updates) give their own cost; sampled once per 30 frames and averaged over the run, so the
  // figure covers the whole run rather than its last second.
  const auto updateStatus = [](rviz::Display* display) -> rviz::Property* {
    for (int c = 0; c < display->numChildren(); ++c) {
      // The status list's name carries its level ("Status: Ok"): found by type.
      auto* statuses = dynamic_cast<rviz::StatusProperty*>(display->childAt(c));
      rviz::Property* update = statuses ? childNamed(statuses, "Update") : nullptr;
      if (update && !update->getValue().toString().isEmpty()) return update;
    }
    return nullptr;
  };
  double display_ms_sum = 0.0;
  int display_samples = 0;
  bool sampling = false;
  const auto sampleDisplays = [&] {
    for (rviz::Display* display : displays) {
      if (rviz::Property* update = updateStatus(display)) {
        display_ms_sum += update->getValue().toString().split(' ').front().toDouble();
        ++display_samples;
      }
    }
  };
  // Seconds from the program's start until every display has drawn its human once (DressedHuman:
  // its "Surfaces" status exists); -1 for displays that do not say, or if one never did.
  double first_frame_seconds = -1.0;
  const auto allDrawn = [&] {
    for (rviz::Display* display : displays) {
      bool drawn = false;
      for (int c = 0; !drawn && c < display->numChildren(); ++c) {
        auto* statuses = dynamic_cast<rviz::StatusProperty*>(display->childAt(c));
        drawn = statuses != nullptr && childNamed(statuses, "Surfaces") != nullptr;
      }
      if (!drawn) return false;
    }
    return true;
  };
  const auto period = std::chrono::microseconds(33333);  // rviz's default 30 fps
  auto run = [&](double duration, int& frames) {
    frames = 0;
    const auto start = std::chrono::steady_clock::now();
    auto next = start;
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < duration) {
      frame();
      ++frames;
      if (first_frame_seconds < 0.0 && allDrawn()) {
        first_frame_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - program_start).count();
      }
      if (sampling && frames % 30 == 0) sampleDisplays();
      next += period;
      std::this_thread::sleep_until(next);
      if (std::chrono::steady_clock::now() > next + period) next = std::chrono::steady_clock::now();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  int frames = 0;
  run(5.0, frames);  // warm-up: TF arrives, relief maps generated, buffers sized
  if (!screenshot.isEmpty()) {
    const int dot = screenshot.lastIndexOf('.');
    const QString start = dot < 0 ? screenshot + "_start" : screenshot.left(dot) + "_start" + screenshot.mid(dot);
    panel.getRenderWindow()->writeContentsToFile(start.toStdString());
  }
  const double cpu_before = processCpuSeconds();
  sampling = true;
  const double wall = run(seconds, frames);
  const double cpu = processCpuSeconds() - cpu_before;
  int measured = 0;
  for (rviz::Display* display : displays) {
    measured += updateStatus(display) ? 1 : 0;
    for (int c = 0; c < display->numChildren(); ++c) {
      auto* statuses = dynamic_cast<rviz::StatusProperty*>(display->childAt(c));
      // Warnings and errors go to stderr: a benchmark of a display that fell back to another
      // path, or failed, must say so.
      for (int s = 0; statuses && s < statuses->numChildren(); ++s) {
        auto* status = dynamic_cast<rviz::StatusProperty*>(statuses->childAt(s));
        // What the first display draws (DressedHuman: parts and triangles), for the table.
        if (status && display == displays.front() && status->getName() == "Surfaces") {
          std::fprintf(stderr, "surfaces %s\n", status->getValue().toString().toStdString().c_str());
        }
        // Which vertex path "Automatic" took (bench/rviz_scaling.py sets it beside the measured ones).
        if (status && display == displays.front() && status->getName() == "Vertex Evaluation") {
          std::fprintf(stderr, "vertex_evaluation %s\n", status->getValue().toString().toStdString().c_str());
        }
        if (status && status->getLevel() != rviz::StatusProperty::Ok) {
          std::fprintf(stderr, "status %s: %s\n", status->getName().toStdString().c_str(),
                       status->getValue().toString().toStdString().c_str());
        }
      }
    }
  }
  if (!screenshot.isEmpty()) panel.getRenderWindow()->writeContentsToFile(screenshot.toStdString());
  std::printf(
      "class=%s count=%d fps=%.2f cpu_percent=%.1f cpu_ms_per_frame=%.3f display_ms=%.3f measured=%d "
      "rss_mb=%.1f first_frame_s=%.2f\n",
      argv[1], count, frames / wall, 100.0 * cpu / wall, 1000.0 * cpu / frames,
      display_samples ? display_ms_sum / display_samples : -1.0, measured, residentMegabytes(), first_frame_seconds);
  return 0;
}
