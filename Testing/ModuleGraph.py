"""The module graph CMake declares (cmake/RiemannModuleGraph.cmake), read.

The build writes RiemannModuleGraph.json: for each Riemann library, its
folder, kind and link dependencies as declared in CMake (public ones in
"interface"). This module turns it into what the architecture checks need:
each library's Riemann dependencies, direct and transitive, and its
third-party targets. Nothing here declares a dependency.
"""
import json
import re

# The wrappers of generator expressions around a target name:
# "$<LINK_ONLY:VTK::CommonCore>" -> "VTK::CommonCore".
WRAPPER = re.compile(r"\$<[A-Z_]+:|>")


def target_names(entries):
    return [WRAPPER.sub("", entry) for entry in entries if WRAPPER.sub("", entry)]


class ModuleGraph:
    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            raw = json.load(f)
        self.libraries = {}
        for name, entry in raw.items():
            link = target_names(entry["link"])
            public = set(target_names(entry["interface"]))
            self.libraries[name] = {
                "folder": entry["folder"],
                "kind": entry["kind"],
                "riemann": [d for d in link if d.startswith("Riemann::")],
                "public": sorted(d for d in public if d.startswith("Riemann::")),
                "third_party": [d for d in link if not d.startswith("Riemann::")],
            }

    def names(self):
        return sorted(self.libraries)

    def folder(self, name):
        return self.libraries[name]["folder"]

    def by_folder(self):
        return {entry["folder"]: name for name, entry in self.libraries.items()}

    def direct(self, name):
        """The Riemann libraries `name` links, as declared."""
        return list(self.libraries[name]["riemann"])

    def closure(self, name):
        """Every Riemann library `name` depends on, directly or through others."""
        seen, stack = set(), self.direct(name)
        while stack:
            other = stack.pop()
            if other in seen or other not in self.libraries:
                continue
            seen.add(other)
            stack.extend(self.direct(other))
        return seen

    @staticmethod
    def file_name(name):
        """Riemann::CommonMetric -> RiemannCommonMetric (libRiemannCommonMetric.so)."""
        return "Riemann" + name.split("::", 1)[1]
