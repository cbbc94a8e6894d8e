/**
 * @file StudioScripting.h
 * @brief What the `studio` Python module does to the window's document, one
 * call by name with JSON arguments (StudioPython.h turns Python calls into
 * these): open, items, add, set, get, remove, show, rename, metric, time,
 * parameter, observer, undo, redo, save, project, screenshot,
 * export_animation, render, wait, cancel, running, select, dock. Every change
 * goes through the same paths as the mouse (so it is undoable and marks the
 * document modified). Errors are thrown as std::runtime_error with the
 * message the window would show.
 */
#ifndef RiemannStudio_StudioScripting_h
#define RiemannStudio_StudioScripting_h

#include <nlohmann/json.hpp>

#include <string>

namespace riemann
{
namespace studio
{
class StudioMainWindow;

/// Runs `name(args...)` on `window`; returns its result (null for none).
nlohmann::json CallStudio(StudioMainWindow& window, const std::string& name, const nlohmann::json& args);
}
}

#endif
