// tide.World: a scene (file or dict, through the scene parser) as a World; stepping with the
// GIL released and Ctrl-C checked between steps; particle arrays as numpy views; gauges,
// probes, obstacle poses; blocks, emitters and obstacles added from dicts.
#include <atomic>
#include <chrono>
#include <cstring>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <tide/io/scene.hpp>

#include "bindings.hpp"

namespace tide::python {

namespace {

/// Keys of a scene that say what a block, emitter or obstacle added later is measured against
/// (units, domain, resolution, materials); the parser needs them to read one.
constexpr const char* kContextKeys[] = {"name",     "unit_scale", "domain",    "gravity",       "particle_spacing",
                                        "end_time", "solver",     "materials", "material_pairs"};

/// Ctrl-C, looked at between steps (advance, settle) at most every 20 ms: taking the GIL back
/// after every step would wait on any busy Python thread each time. Throws the
/// KeyboardInterrupt out of the stepping loop.
class SignalPoll {
public:
    void operator()() {
        const auto now = std::chrono::steady_clock::now();
        if (now - last_ < std::chrono::milliseconds(20)) return;
        last_ = now;
        checkSignals();
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// A World made from a scene, with the scene kept for what Python asks later (gauges, probes,
/// frame rate, material names) and to read added blocks, emitters and obstacles.
class PyWorld {
public:
    PyWorld(const std::string& text, const std::string& source, const std::filesystem::path& baseDirectory, int threads,
            std::uint32_t capacity, bool settle)
        : scene_(io::parseScene(text, source, baseDirectory)), root_(nlohmann::json::parse(text)),
          baseDirectory_(baseDirectory) {
        scene_.world.threads = threads;
        if (capacity > 0) scene_.world.capacity = capacity;
        py::gil_scoped_release nogil;
        world_ = std::make_unique<World>(io::buildWorld(scene_));
        // Up to the capacity, adding particles never moves the arrays numpy views point at.
        world_->reserve(scene_.world.capacity);
        SignalPoll poll;
        if (settle && scene_.settleTime > 0.0) world_->settle(scene_.settleTime, scene_.settleSpeed, [&] { poll(); });
    }

    World& world() { return *world_; }
    const World& world() const { return *world_; }
    const io::Scene& scene() const { return scene_; }

    double step(std::optional<double> maxDt) {
        Busy busy(*this);
        const double limit = maxDt ? *maxDt : static_cast<double>(world_->def().solver.maxDt);
        py::gil_scoped_release nogil;
        return world_->step(limit);
    }

    void advance(double seconds) {
        Busy busy(*this);
        py::gil_scoped_release nogil;
        SignalPoll poll;
        world_->advance(seconds, [&] { poll(); });
    }

    py::dict settle(std::optional<double> seconds, std::optional<float> speed) {
        Busy busy(*this);
        SettleReport r;
        {
            py::gil_scoped_release nogil;
            SignalPoll poll;
            r = world_->settle(seconds ? *seconds : scene_.settleTime, speed ? *speed : scene_.settleSpeed, [&] { poll(); });
        }
        py::dict d;
        d["seconds"] = r.seconds;
        d["steps"] = r.steps;
        d["max_speed"] = r.maxSpeed;
        d["quiet"] = r.quiet;
        return d;
    }

    void setVelocities(const py::array_t<float, py::array::c_style | py::array::forcecast>& v) {
        Busy busy(*this);
        const std::uint32_t n = world_->particles().size();
        if (v.ndim() != 2 || v.shape(0) != n || v.shape(1) != 3) {
            std::ostringstream msg;
            msg << "velocities: must have shape (" << n << ", 3), got (";
            for (py::ssize_t k = 0; k < v.ndim(); ++k) msg << (k ? ", " : "") << v.shape(k);
            msg << (v.ndim() == 1 ? ",)" : ")");
            throw py::value_error(msg.str());
        }
        const float* x = v.data();
        for (std::size_t k = 0; k < std::size_t{n} * 3; ++k)
            if (!std::isfinite(x[k])) {
                std::ostringstream msg;
                msg << "velocities[" << k / 3 << ", " << k % 3 << "]: must be finite, got " << x[k];
                throw py::value_error(msg.str());
            }
        if (world_->def().dimensions == 2)  // a 2D world's particles stay in the plane z = 0
            for (std::size_t i = 0; i < std::size_t{n}; ++i)
                if (x[3 * i + 2] != 0.0f) {
                    std::ostringstream msg;
                    msg << "velocities[" << i << ", 2]: must be 0 in a 2D world, got " << x[3 * i + 2];
                    throw py::value_error(msg.str());
                }
        std::memcpy(world_->velocities().data(), x, sizeof(float) * 3 * n);
    }

    /// One block, emitter or obstacle (`key`: "blocks", "emitters", "obstacles"), read by the
    /// scene parser as the only entry of its list in this world's scene; problems name it
    /// `block`, `emitter` or `obstacle` instead of `blocks[0]`.
    io::Scene parseOne(const char* key, const char* name, const std::string& entryJson) const {
        nlohmann::json one = nlohmann::json::object();
        for (const char* k : kContextKeys)
            if (root_.contains(k)) one[k] = root_[k];
        one[key] = nlohmann::json::array({nlohmann::json::parse(entryJson)});
        try {
            return io::parseScene(one.dump(), name, baseDirectory_);
        } catch (io::SceneError& e) {
            const std::string prefix = std::string(key) + "[0]";
            for (std::string& p : e.problems)
                if (p.compare(0, prefix.size(), prefix) == 0) p = name + p.substr(prefix.size());
            throw;
        }
    }

    std::uint32_t addBlock(const std::string& entryJson) {
        Busy busy(*this);
        const io::Scene one = parseOne("blocks", "block", entryJson);
        const BlockDef& b = one.blocks.at(0);
        const std::uint32_t count = world_->countBlock(b);
        switch (world_->addBlock(b)) {
            case AddStatus::Added: return count;
            case AddStatus::OutsideDomain: throw py::value_error("block: lies outside the domain");
            case AddStatus::OverCapacity: {
                std::ostringstream msg;
                msg << "block: " << count << " more particles would exceed the world's capacity of "
                    << world_->def().capacity << " (it holds " << world_->particles().size()
                    << "); make the world with tide.World(scene, capacity=N)";
                throw py::value_error(msg.str());
            }
        }
        return 0;
    }

    std::uint32_t addEmitter(const std::string& entryJson) {
        Busy busy(*this);
        return world_->addEmitter(parseOne("emitters", "emitter", entryJson).emitters.at(0));
    }

    std::uint32_t addObstacle(const std::string& entryJson) {
        Busy busy(*this);
        world_->addObstacle(parseOne("obstacles", "obstacle", entryJson).obstacles.at(0));
        return static_cast<std::uint32_t>(world_->obstacles().size() - 1);
    }

private:
    /// Refuses a second call into the World while one has it (another Python thread can run
    /// while a step holds no GIL).
    struct Busy {
        explicit Busy(PyWorld& w) : world(w) {
            if (world.busy_.exchange(true)) throw std::runtime_error("tide.World: busy stepping in another thread");
        }
        ~Busy() { world.busy_ = false; }
        PyWorld& world;
    };

    io::Scene scene_;
    nlohmann::json root_;
    std::filesystem::path baseDirectory_;
    std::unique_ptr<World> world_;
    std::atomic<bool> busy_{false};
};

PyWorld& self(py::handle h) { return h.cast<PyWorld&>(); }

py::array vec3View(py::handle owner, const std::vector<glm::vec3>& v) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    return view(owner, py::dtype::of<float>(), {static_cast<py::ssize_t>(v.size()), 3},
                {static_cast<py::ssize_t>(sizeof(glm::vec3)), static_cast<py::ssize_t>(sizeof(float))}, v.data());
}

template <class T>
py::array scalarView(py::handle owner, const std::vector<T>& v) {
    return view(owner, py::dtype::of<T>(), {static_cast<py::ssize_t>(v.size())}, {static_cast<py::ssize_t>(sizeof(T))},
                v.data());
}

/// The address of one of the engine's arrays, for tests that check a view is no copy.
std::uintptr_t address(const World& w, const std::string& name) {
    const ParticleStore& p = w.particles();
    if (name == "positions") return reinterpret_cast<std::uintptr_t>(p.position.data());
    if (name == "velocities") return reinterpret_cast<std::uintptr_t>(p.velocity.data());
    if (name == "densities") return reinterpret_cast<std::uintptr_t>(p.density.data());
    if (name == "pressures") return reinterpret_cast<std::uintptr_t>(p.pressure.data());
    if (name == "materials") return reinterpret_cast<std::uintptr_t>(p.material.data());
    if (name == "ids") return reinterpret_cast<std::uintptr_t>(p.id.data());
    if (name == "concentrations") return reinterpret_cast<std::uintptr_t>(p.concentration.data());
    throw py::value_error("name: not a particle array, got \"" + name + "\"");
}

/// An (n, width) float64 array with entry (i, k) = value(i, k).
template <class Value>
py::array_t<double> table(std::size_t n, py::ssize_t width, Value value) {
    py::array_t<double> out({static_cast<py::ssize_t>(n), width});
    auto o = out.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(n); ++i)
        for (py::ssize_t k = 0; k < width; ++k) o(i, k) = value(static_cast<std::size_t>(i), static_cast<int>(k));
    return out;
}

/// Loads on the solids (World::solids order) as numpy: names and (s, 3) float64 arrays, N and N·m.
py::dict loadsDict(const World& w, const std::vector<SolidLoad>& loads) {
    std::vector<std::string> names;
    for (const SolidInfo& s : w.solids()) names.push_back(s.name);
    py::dict d;
    d["names"] = names;
    d["force"] = table(loads.size(), 3, [&](std::size_t i, int c) { return loads[i].force()[c]; });
    d["pressure_force"] = table(loads.size(), 3, [&](std::size_t i, int c) { return loads[i].pressureForce[c]; });
    d["viscous_force"] = table(loads.size(), 3, [&](std::size_t i, int c) { return loads[i].viscousForce[c]; });
    d["moment"] = table(loads.size(), 3, [&](std::size_t i, int c) { return loads[i].moment[c]; });
    return d;
}

/// The dynamic obstacles' state (World::bodies order) as numpy: names and (b, 3) / (b, 4)
/// float64 arrays, as bodies.csv writes them.
py::dict bodiesDict(const World& w) {
    const std::vector<BodyState> bodies = w.bodies();
    const std::size_t n = bodies.size();
    std::vector<std::string> names;
    std::vector<std::uint32_t> obstacles;
    for (const BodyState& b : bodies) {
        names.push_back(b.name);
        obstacles.push_back(b.obstacle);
    }
    const auto position = table(n, 3, [&](std::size_t i, int k) { return bodies[i].position[k]; });
    const auto velocity = table(n, 3, [&](std::size_t i, int k) { return bodies[i].velocity[k]; });
    const auto angular = table(n, 3, [&](std::size_t i, int k) { return bodies[i].angularVelocity[k]; });
    const auto contact = table(n, 3, [&](std::size_t i, int k) { return bodies[i].contactForce[k]; });
    // (w, x, y, z), as bodies.csv.
    const auto orientation = table(n, 4, [&](std::size_t i, int k) {
        const auto& q = bodies[i].orientation;
        return k == 0 ? q.w : (k == 1 ? q.x : (k == 2 ? q.y : q.z));
    });
    py::dict d;
    d["names"] = names;
    d["obstacles"] = obstacles;
    d["position"] = position;
    d["orientation"] = orientation;
    d["velocity"] = velocity;
    d["angular_velocity"] = angular;
    d["contact_force"] = contact;
    return d;
}

}  // namespace

void bindWorld(py::module_& m) {
    py::class_<PyWorld>(m, "World", py::dynamic_attr(), R"(One simulation, built from a scene (see tide.World).)")
        .def(py::init<const std::string&, const std::string&, const std::filesystem::path&, int, std::uint32_t, bool>(),
             py::arg("scene_json"), py::arg("source"), py::arg("base_directory"), py::arg("threads") = 0,
             py::arg("capacity") = 0, py::arg("settle") = true)
        .def("step", &PyWorld::step, py::arg("max_dt") = py::none(),
             "Take one time step (at most max_dt s; default the solver's max_dt); returns its length, s.")
        .def("advance", &PyWorld::advance, py::arg("seconds"),
             "Advance exactly `seconds` in adaptive steps (GIL released; Ctrl-C stops between steps).")
        .def("settle", &PyWorld::settle, py::arg("seconds") = py::none(), py::arg("speed") = py::none(),
             "World::settle: let the particles find their rest arrangement with the clock held, then zero "
             "the velocities. Defaults: the scene's settle.time and settle.speed. Returns a report dict.")
        .def_property_readonly("time", [](const PyWorld& w) { return w.world().time(); }, "Simulated time, s.")
        .def_property_readonly("particle_count", [](const PyWorld& w) { return w.world().particles().size(); })
        .def_property_readonly("steps", [](const PyWorld& w) { return w.world().stats().steps; })
        .def_property_readonly("positions", [](py::object o) { return vec3View(o, self(o).world().particles().position); },
                               "(n, 3) float32, m: a read-only view of the engine's array (no copy).")
        .def_property_readonly("velocities", [](py::object o) { return vec3View(o, self(o).world().particles().velocity); },
                               "(n, 3) float32, m/s: read-only view; change them with set_velocities().")
        .def_property_readonly("densities", [](py::object o) { return scalarView(o, self(o).world().particles().density); },
                               "(n,) float32, kg/m³: read-only view.")
        .def_property_readonly("pressures", [](py::object o) { return scalarView(o, self(o).world().particles().pressure); },
                               "(n,) float32, Pa: read-only view.")
        .def_property_readonly("materials", [](py::object o) { return scalarView(o, self(o).world().particles().material); },
                               "(n,) uint16 material index (see material_names): read-only view.")
        .def_property_readonly("ids", [](py::object o) { return scalarView(o, self(o).world().particles().id); },
                               "(n,) uint32 stable particle id (reordering moves particles, not ids): read-only view.")
        .def_property_readonly("concentrations",
                               [](py::object o) { return scalarView(o, self(o).world().particles().concentration); },
                               "(n,) float32 dye concentration: read-only view.")
        .def("set_velocities", &PyWorld::setVelocities, py::arg("velocities"),
             "Replace every particle's velocity ((n, 3), m/s, finite), between steps.")
        .def("_address", [](const PyWorld& w, const std::string& name) { return address(w.world(), name); },
             py::arg("name"), "The address of the engine's array `name` (tests: views are no copies).")
        .def_property_readonly("stats", [](const PyWorld& w) { return statsDict(w.world()); })
        .def("_surface_heights",
             [](const PyWorld& w, const py::array_t<float, py::array::c_style | py::array::forcecast>& x,
                const py::array_t<float, py::array::c_style | py::array::forcecast>& z) {
                 if (x.size() != z.size()) throw py::value_error("x, z: must have the same size");
                 py::array_t<float> out(x.size());
                 const float* px = x.data();
                 const float* pz = z.data();
                 float* po = out.mutable_data();
                 py::gil_scoped_release nogil;
                 for (py::ssize_t k = 0; k < x.size(); ++k) po[k] = w.world().surfaceHeight(px[k], pz[k]);
                 return out;
             })
        .def("_probe",
             [](const PyWorld& w, const py::array_t<float, py::array::c_style | py::array::forcecast>& points) {
                 if (points.ndim() != 2 || points.shape(1) != 3) throw py::value_error("points: must have shape (m, 3)");
                 const py::ssize_t n = points.shape(0);
                 py::array_t<float> out({n, py::ssize_t{5}});
                 const float* p = points.data();
                 float* o = out.mutable_data();
                 py::gil_scoped_release nogil;
                 for (py::ssize_t k = 0; k < n; ++k) {
                     const ProbeSample s = w.world().probe({p[3 * k], p[3 * k + 1], p[3 * k + 2]});
                     const float row[5] = {s.density, s.pressure, s.velocity.x, s.velocity.y, s.velocity.z};
                     std::memcpy(o + 5 * k, row, sizeof row);
                 }
                 return out;
             })
        .def_property_readonly("gauge_names",
                               [](const PyWorld& w) {
                                   std::vector<std::string> names;
                                   for (const auto& g : w.scene().gauges) names.push_back(g.name);
                                   return names;
                               })
        .def_property_readonly("gauge_positions",
                               [](const PyWorld& w) {
                                   py::array_t<float> a({static_cast<py::ssize_t>(w.scene().gauges.size()), py::ssize_t{2}});
                                   auto r = a.mutable_unchecked<2>();
                                   for (std::size_t i = 0; i < w.scene().gauges.size(); ++i) {
                                       r(i, 0) = w.scene().gauges[i].x;
                                       r(i, 1) = w.scene().gauges[i].z;
                                   }
                                   return a;
                               },
                               "(g, 2) float32: the scene's gauges' (x, z), m.")
        .def_property_readonly("probe_names",
                               [](const PyWorld& w) {
                                   std::vector<std::string> names;
                                   for (const auto& p : w.scene().probes) names.push_back(p.name);
                                   return names;
                               })
        .def_property_readonly("probe_positions",
                               [](const PyWorld& w) {
                                   py::array_t<float> a({static_cast<py::ssize_t>(w.scene().probes.size()), py::ssize_t{3}});
                                   auto r = a.mutable_unchecked<2>();
                                   for (std::size_t i = 0; i < w.scene().probes.size(); ++i)
                                       for (int c = 0; c < 3; ++c) r(i, c) = w.scene().probes[i].position[c];
                                   return a;
                               },
                               "(p, 3) float32: the scene's probes' positions, m.")
        .def("_add_block", &PyWorld::addBlock, py::arg("entry_json"))
        .def("_add_emitter", &PyWorld::addEmitter, py::arg("entry_json"))
        .def("_add_obstacle", &PyWorld::addObstacle, py::arg("entry_json"))
        .def("set_emitter_active",
             [](PyWorld& w, std::uint32_t emitter, bool active) {
                 if (emitter >= w.world().emitterCount())
                     throw py::value_error("emitter: no emitter " + std::to_string(emitter) + " (the world has " +
                                           std::to_string(w.world().emitterCount()) + ")");
                 w.world().setEmitterActive(emitter, active);
             },
             py::arg("emitter"), py::arg("active"))
        .def_property_readonly("emitter_count", [](const PyWorld& w) { return w.world().emitterCount(); })
        .def_property_readonly("obstacle_count",
                               [](const PyWorld& w) { return static_cast<std::uint32_t>(w.world().obstacles().size()); })
        .def("obstacle_pose",
             [](const PyWorld& w, std::uint32_t index, std::optional<double> t) {
                 if (index >= w.world().obstacles().size())
                     throw py::value_error("index: no obstacle " + std::to_string(index) + " (the world has " +
                                           std::to_string(w.world().obstacles().size()) + ")");
                 const ObstaclePose pose = w.world().obstaclePose(index, t ? *t : w.world().time());
                 py::array_t<float> rotation({py::ssize_t{3}, py::ssize_t{3}}), translation(py::ssize_t{3});
                 auto r = rotation.mutable_unchecked<2>();
                 for (int row = 0; row < 3; ++row)
                     for (int col = 0; col < 3; ++col) r(row, col) = pose.rotation[col][row];  // glm is column-major
                 for (int c = 0; c < 3; ++c) translation.mutable_at(c) = pose.translation[c];
                 return py::make_tuple(rotation, translation);
             },
             py::arg("index"), py::arg("t") = py::none(),
             "(rotation (3, 3), translation (3,)) of obstacle `index` at time t (default: now): a point x0 of "
             "its rest pose is at rotation @ x0 + translation.")
        .def_property_readonly("wave_maker_count", [](const PyWorld& w) { return w.world().waveMakerCount(); })
        .def("wave_maker_displacement",
             [](const PyWorld& w, std::uint32_t index, std::optional<double> t) {
                 if (index >= w.world().waveMakerCount()) throw py::value_error("index: no wave maker " + std::to_string(index));
                 return w.world().waveMakerDisplacement(index, t ? *t : w.world().time());
             },
             py::arg("index") = 0, py::arg("t") = py::none(),
             "Horizontal displacement of the wave maker's face at the still-water level, m.")
        .def_property_readonly("solid_names",
                               [](const PyWorld& w) {
                                   std::vector<std::string> names;
                                   for (const SolidInfo& solid : w.world().solids()) names.push_back(solid.name);
                                   return names;
                               },
                               "The solids the fluid loads: the container's faces, wave makers, obstacles.")
        .def("loads", [](const PyWorld& w) { return loadsDict(w.world(), w.world().solidLoads()); },
             "The fluid's load on each solid over the last step: a dict of names and (s, 3) arrays force, "
             "pressure_force, viscous_force (N) and moment (N·m, about the solid's reference point).")
        .def("take_mean_loads", [](PyWorld& w) { return loadsDict(w.world(), w.world().takeMeanSolidLoads()); },
             "As loads(), averaged over the time stepped since the last call (which starts a new average).")
        .def("bodies", [](const PyWorld& w) { return bodiesDict(w.world()); },
             "The floating bodies (obstacles with \"dynamic\": true) now: a dict of names, their obstacle "
             "indices, and (b, 3) arrays position (centre of mass, m), velocity (m/s), angular_velocity "
             "(rad/s), contact_force (N), and (b, 4) orientation (w, x, y, z), as bodies.csv writes them.")
        .def_property_readonly("total_mass", [](const PyWorld& w) { return w.world().totalMass(); })
        .def_property_readonly("escaped_particles", [](const PyWorld& w) { return w.world().countEscapedParticles(); })
        .def_property_readonly("material_names",
                               [](const PyWorld& w) {
                                   std::vector<std::string> names;
                                   for (const MaterialDef& mat : w.world().materials()) names.push_back(mat.name);
                                   return names;
                               })
        .def_property_readonly("name", [](const PyWorld& w) { return w.scene().name; })
        .def_property_readonly("end_time", [](const PyWorld& w) { return w.scene().endTime; }, "The scene's end_time, s.")
        .def_property_readonly("fps", [](const PyWorld& w) { return w.scene().output.fps; }, "The scene's output.fps.")
        .def_property_readonly("formats",
                               [](const PyWorld& w) {
                                   std::vector<std::string> names;
                                   for (const io::Format f : w.scene().output.formats) names.emplace_back(io::extension(f));
                                   return names;
                               },
                               "The scene's output.formats.")
        .def_property_readonly("particle_spacing", [](const PyWorld& w) { return w.world().def().particleSpacing; })
        .def_property_readonly("support_radius", [](const PyWorld& w) { return w.world().supportRadius(); })
        .def_property_readonly("capacity", [](const PyWorld& w) { return w.world().def().capacity; })
        .def_property_readonly("threads", [](const PyWorld& w) { return w.world().threads(); })
        .def_property_readonly("domain",
                               [](const PyWorld& w) {
                                   const WorldDef& d = w.world().def();
                                   return py::make_tuple(py::make_tuple(d.domainMin.x, d.domainMin.y, d.domainMin.z),
                                                         py::make_tuple(d.domainMax.x, d.domainMax.y, d.domainMax.z));
                               },
                               "((x, y, z) min, (x, y, z) max) of the container, m.");
}

const World& worldOf(py::handle h) { return self(h).world(); }

}  // namespace tide::python
