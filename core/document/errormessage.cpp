#include "document/errormessage.h"

#include <new>

#include "engine/util/error.h"

namespace sylva::doc {

ErrorReport describeError(std::exception_ptr error, const std::string& context) {
    const std::string where = context.empty() ? std::string() : context + ": ";
    try {
        std::rethrow_exception(error);
    } catch (const Cancelled&) {
        return {ErrorReport::Kind::Cancelled, "cancelled"};
    } catch (const InvalidInput& e) {
        if (e.diagnostics().empty()) return {ErrorReport::Kind::InvalidInput, e.what()};
        std::string lines;
        for (const Diagnostic& d : e.diagnostics())
            lines += (lines.empty() ? "" : "\n") + d.format();
        return {ErrorReport::Kind::InvalidInput, lines};
    } catch (const LimitExceeded& e) {
        return {ErrorReport::Kind::LimitExceeded, e.what()};
    } catch (const IoError& e) {
        return {ErrorReport::Kind::Io, e.what()};
    } catch (const std::bad_alloc&) {
        return {ErrorReport::Kind::OutOfMemory, where + "out of memory"};
    } catch (const std::exception& e) {
        return {ErrorReport::Kind::Other, where + "unexpected error: " + e.what()};
    } catch (...) {
        return {ErrorReport::Kind::Other, where + "unexpected error"};
    }
}

} // namespace sylva::doc
