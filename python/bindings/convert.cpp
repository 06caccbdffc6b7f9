#include "convert.h"

#include <deque>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <new>

#include <dlfcn.h>

#include "document/errormessage.h"
#include "engine/export/formats.h"
#include "engine/util/error.h"

namespace sylva::python {

namespace fs = std::filesystem;

sylva::Value toValue(const py::handle& o) {
    if (o.is_none()) return {};
    if (py::isinstance<py::bool_>(o)) return sylva::Value(o.cast<bool>());
    if (py::isinstance<py::int_>(o) || py::isinstance<py::float_>(o))
        return sylva::Value(o.cast<double>());
    if (py::isinstance<py::str>(o)) return sylva::Value(o.cast<std::string>());
    if (py::isinstance<py::dict>(o)) {
        sylva::Value::Object obj;
        for (const auto& [k, v] : o.cast<py::dict>())
            obj[py::str(k).cast<std::string>()] = toValue(v);
        return sylva::Value(std::move(obj));
    }
    // numpy scalars and arrays: through their Python equivalents.
    if (py::hasattr(o, "tolist") && !py::isinstance<py::sequence>(o))
        return toValue(o.attr("tolist")());
    if (py::isinstance<py::sequence>(o) || py::isinstance<py::array>(o)) {
        sylva::Value::Array arr;
        for (const py::handle& v : o)
            arr.push_back(toValue(v));
        return sylva::Value(std::move(arr));
    }
    throw InvalidInput("cannot use a Python " +
                       py::str(py::type::of(o).attr("__name__")).cast<std::string>() +
                       " as a parameter value");
}

py::object fromValue(const sylva::Value& v) {
    if (v.isNull()) return py::none();
    if (v.isBool()) return py::bool_(v.toBool());
    if (v.isNumber()) {
        const double d = v.toNumber();
        if (d == double(static_cast<long long>(d)) && std::abs(d) < 9e15)
            return py::int_(static_cast<long long>(d));
        return py::float_(d);
    }
    if (v.isString()) return py::str(v.toString());
    if (v.isArray()) {
        py::list l;
        for (const sylva::Value& x : v.toArray())
            l.append(fromValue(x));
        return l;
    }
    py::dict d;
    for (const auto& [k, x] : v.toObject())
        d[py::str(k)] = fromValue(x);
    return d;
}

glm::vec3 toVec3(const py::handle& o, const char* what) {
    std::vector<double> seq;
    try {
        seq = py::reinterpret_borrow<py::object>(o).cast<std::vector<double>>();
    } catch (const py::cast_error&) {
        throw InvalidInput(std::string(what) + " needs three numbers (x, y, z)");
    }
    if (seq.size() != 3) throw InvalidInput(std::string(what) + " needs three numbers (x, y, z)");
    return {float(seq[0]), float(seq[1]), float(seq[2])};
}

py::tuple fromVec3(const glm::vec3& v) {
    return py::make_tuple(v.x, v.y, v.z);
}

std::string toPath(const py::handle& o) {
    if (py::isinstance<py::str>(o)) return o.cast<std::string>();
    if (py::hasattr(o, "__fspath__")) return py::str(o.attr("__fspath__")()).cast<std::string>();
    throw InvalidInput("expected a path (str or os.PathLike), got a Python " +
                       py::str(py::type::of(o).attr("__name__")).cast<std::string>());
}

namespace {

template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> rows3(const py::handle& o,
                                                                const char* what) {
    py::array_t<T, py::array::c_style | py::array::forcecast> a;
    try {
        a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(o);
    } catch (const py::error_already_set&) {
    }
    if (!a) throw InvalidInput(std::string(what) + " must be an array of shape (N, 3)");
    if (a.size() == 0) return a;
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw InvalidInput(
            std::string(what) + " must be an array of shape (N, 3), got " +
            std::to_string(a.ndim()) + " dimensions" +
            (a.ndim() == 2 ? " with " + std::to_string(a.shape(1)) + " columns" : std::string()));
    return a;
}

} // namespace

std::vector<glm::vec3> toVec3Array(const py::handle& o, const char* what) {
    const auto a = rows3<float>(o, what);
    std::vector<glm::vec3> out(a.size() / 3);
    const float* p = a.data();
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
        if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
            throw InvalidInput(std::string(what) + ": vertex " + std::to_string(i) +
                               " is not finite");
    }
    return out;
}

std::vector<glm::uvec3> toTriangleArray(const py::handle& o, const char* what) {
    const auto a = rows3<long long>(o, what);
    std::vector<glm::uvec3> out(a.size() / 3);
    const long long* p = a.data();
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const long long v = p[3 * i + std::size_t(k)];
            if (v < 0 || v > 0xffffffffLL)
                throw InvalidInput(std::string(what) + ": triangle " + std::to_string(i) +
                                   " has a negative or too large index " + std::to_string(v));
            out[i][k] = static_cast<unsigned>(v);
        }
    }
    return out;
}

PyProgress::PyProgress(py::object callback)
    : mCallback(std::move(callback)), mCaller(std::this_thread::get_id()),
      mLastSignalCheck(std::chrono::steady_clock::now()) {
    if (!mCallback.is_none() && !PyCallable_Check(mCallback.ptr()))
        throw InvalidInput("progress must be a callable f(fraction, stage) or None");
}

PyProgress::~PyProgress() = default;

void PyProgress::stop(py::error_already_set& e) const {
    std::lock_guard lock(mMutex);
    mCancelled = true;
    if (!mError) mError = std::make_unique<py::error_already_set>(std::move(e));
}

void PyProgress::report(double fraction, std::string_view stage) {
    // Worker threads may report too; only the thread that holds the Python call talks to it.
    if (!onCaller() || mCallback.is_none()) return;
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (percent == mLastPercent && stage == mLastStage) return;
    mLastPercent = percent;
    mLastStage = std::string(stage);
    py::gil_scoped_acquire gil;
    try {
        mCallback(fraction, mLastStage);
    } catch (py::error_already_set& e) {
        stop(e);
    }
}

bool PyProgress::isCancelled() const {
    {
        std::lock_guard lock(mMutex);
        if (mCancelled) return true;
    }
    if (!onCaller()) return false;
    // Python's SIGINT handler only sets a flag; run it (at most every 20 ms).
    const auto now = std::chrono::steady_clock::now();
    if (now - mLastSignalCheck < std::chrono::milliseconds(20)) return false;
    mLastSignalCheck = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
        py::error_already_set e;
        stop(e);
        return true;
    }
    return false;
}

void PyProgress::rethrowPythonError() {
    std::unique_ptr<py::error_already_set> e;
    {
        std::lock_guard lock(mMutex);
        e = std::move(mError);
    }
    if (e) throw std::move(*e);
}

void registerErrorTranslator() {
    py::register_exception_translator([](std::exception_ptr p) {
        if (!p) return;
        try {
            std::rethrow_exception(p);
        } catch (const py::error_already_set&) {
            throw;
        } catch (const py::builtin_exception&) {
            throw;
        } catch (const std::exception&) {
            const doc::ErrorReport r = doc::describeError(p);
            using K = doc::ErrorReport::Kind;
            switch (r.kind) {
            case K::Io:
                PyErr_SetString(PyExc_OSError, r.message.c_str());
                return;
            case K::Cancelled:
                PyErr_SetString(PyExc_KeyboardInterrupt, "interrupted; no output written");
                return;
            case K::OutOfMemory:
                PyErr_SetString(PyExc_MemoryError, r.message.c_str());
                return;
            case K::Other:
                PyErr_SetString(PyExc_RuntimeError, r.message.c_str());
                return;
            default:
                PyErr_SetString(PyExc_ValueError, r.message.c_str());
                return;
            }
        }
    });
}

namespace {

/// The folder of the shared object this code is in (the module), or empty.
fs::path moduleDir() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&moduleDir), &info) == 0 || !info.dli_fname) return {};
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::path(info.dli_fname), ec);
    return ec ? fs::path() : p.parent_path();
}

std::string dataDir(const char* env, const char* sub, const char* probe) {
    if (const char* v = std::getenv(env); v && *v) return v;
    std::error_code ec;
    const fs::path here = moduleDir();
    if (!here.empty()) {
        // <prefix>/lib/python3/dist-packages, <prefix>/lib/python3.11/site-packages, or
        // <prefix>/bin (the editor, whose embedded module calls bindEngine)
        for (const fs::path& c :
             {here / "../../../share/sylva" / sub, here / "../../../../share/sylva" / sub,
              here / "../share/sylva" / sub})
            if (fs::exists(c / probe, ec)) return fs::weakly_canonical(c, ec).string();
    }
#ifdef SYLVA_SOURCE_DIR
    const fs::path source = fs::path(SYLVA_SOURCE_DIR) / sub;
    if (fs::exists(source / probe, ec)) return source.string();
#endif
    return {};
}

} // namespace

std::string presetsDir() {
    return dataDir("SYLVA_PRESETS_DIR", "presets", "ternary-tree.json");
}

const char* withFormats(const char* text) {
    static std::deque<std::string> kept;
    std::string out = text;
    const std::pair<const char*, std::string> keys[] = {
        {"{formats}", exporter::extensionList()},
        {"{wind-rig}",
         exporter::extensionList(
             [](const exporter::FormatRow& r) { return r.wind == exporter::WindSupport::Rig; },
             ", ", ", ")}};
    for (const auto& key : keys)
        for (std::size_t at = out.find(key.first); at != std::string::npos;
             at = out.find(key.first, at))
            out.replace(at, std::string(key.first).size(), key.second);
    return kept.emplace_back(std::move(out)).c_str();
}

std::string resourcesDir() {
    return dataDir("SYLVA_RESOURCES_DIR", "resources", "textures");
}

} // namespace sylva::python
