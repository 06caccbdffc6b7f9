#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <glm/glm.hpp>

#include "engine/util/progress.h"
#include "engine/util/value.h"

namespace sylva::python {

namespace py = pybind11;

/// A Python value (None, bool, int, float, str, dict, list/tuple) as a parameter value.
/// \throw InvalidInput for anything else.
sylva::Value toValue(const py::handle& o);
/// The reverse; whole numbers become ints.
py::object fromValue(const sylva::Value& v);

/// Three numbers (a tuple, list or numpy array) → vec3. \throw InvalidInput naming \p what.
glm::vec3 toVec3(const py::handle& o, const char* what);
py::tuple fromVec3(const glm::vec3& v);

/// A str or os.PathLike as a file path.
std::string toPath(const py::handle& o);

/// Copies \p count rows of \p columns values into a new numpy array of shape (count, columns),
/// or (count,) when \p columns is 0.
template <class T> py::array_t<T> makeArray(const T* data, std::size_t count, std::size_t columns) {
    std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)};
    if (columns > 0) shape.push_back(static_cast<py::ssize_t>(columns));
    py::array_t<T> a(shape);
    const std::size_t n = count * (columns > 0 ? columns : 1);
    if (n > 0) std::copy(data, data + n, a.mutable_data());
    return a;
}

/// (N, 3) float vertices from any array-like. \throw InvalidInput naming \p what.
std::vector<glm::vec3> toVec3Array(const py::handle& o, const char* what);
/// (M, 3) integer triangles from any array-like. \throw InvalidInput naming \p what.
std::vector<glm::uvec3> toTriangleArray(const py::handle& o, const char* what);

/// Progress of a long call made with the GIL released: the Python callback (fraction 0..1,
/// stage name) is called on the calling thread when the percentage or the stage changes, and
/// Ctrl-C (Python's pending signals) or an exception raised by the callback stops the engine at
/// its next check. Construct and destroy it with the GIL held.
class PyProgress : public Progress {
public:
    explicit PyProgress(py::object callback);
    ~PyProgress() override;
    void report(double fraction, std::string_view stage) override;
    bool isCancelled() const override;
    /// After the engine threw Cancelled: raises the KeyboardInterrupt (or the callback's
    /// exception) that caused it. GIL held.
    void rethrowPythonError();

private:
    bool onCaller() const { return std::this_thread::get_id() == mCaller; }
    void stop(py::error_already_set& e) const;

    py::object mCallback;
    std::thread::id mCaller;
    mutable std::mutex mMutex;
    mutable bool mCancelled = false;
    mutable std::unique_ptr<py::error_already_set> mError;
    mutable std::chrono::steady_clock::time_point mLastSignalCheck;
    int mLastPercent = -1;
    std::string mLastStage;
};

/// Runs \p f with the GIL released; a Cancelled caused by Python (Ctrl-C, the callback) is
/// raised as that Python exception.
template <class F> auto withoutGil(PyProgress& progress, F&& f) -> decltype(f()) {
    try {
        py::gil_scoped_release release;
        return f();
    } catch (const Cancelled&) {
        progress.rethrowPythonError();
        throw;
    }
}

/// The engine's and document's exceptions as Python exceptions, with the messages the CLI
/// prints (doc::describeError): InvalidInput/LimitExceeded → ValueError, IoError → OSError,
/// Cancelled → KeyboardInterrupt, bad_alloc → MemoryError, others → RuntimeError.
void registerErrorTranslator();

/// The folders Sylva's data is read from: the presets (species files) and the resources
/// (textures). $SYLVA_PRESETS_DIR / $SYLVA_RESOURCES_DIR, else next to an installed module
/// (<prefix>/share/sylva/...), else the source tree the module was built from.
std::string presetsDir();
/// A docstring with the format table's extensions: "{formats}" as ".obj, .usda, .glb, .gltf or
/// .fbx", "{wind-rig}" as the formats that carry the wind's rig (".glb, .gltf, .fbx"); kept for
/// the process (pybind11 keeps the pointer).
const char* withFormats(const char* text);

std::string resourcesDir();

} // namespace sylva::python
