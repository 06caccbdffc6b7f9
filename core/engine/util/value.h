#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace sylva {

/// A JSON-like parameter value (the engine does not depend on Qt's JSON). Objects keep their
/// keys sorted so that hashing and printing are deterministic.
class Value {
public:
    using Array = std::vector<Value>;
    using Object = std::map<std::string, Value>;

    Value() = default; // null
    Value(std::nullptr_t) {}
    Value(bool b) : mData(b) {}
    Value(double d) : mData(d) {}
    Value(int i) : mData(static_cast<double>(i)) {}
    Value(const char* s) : mData(std::string(s)) {}
    Value(std::string s) : mData(std::move(s)) {}
    Value(Array a) : mData(std::move(a)) {}
    Value(Object o) : mData(std::move(o)) {}

    bool isNull() const { return std::holds_alternative<std::monostate>(mData); }
    bool isBool() const { return std::holds_alternative<bool>(mData); }
    bool isNumber() const { return std::holds_alternative<double>(mData); }
    bool isString() const { return std::holds_alternative<std::string>(mData); }
    bool isArray() const { return std::holds_alternative<Array>(mData); }
    bool isObject() const { return std::holds_alternative<Object>(mData); }

    /// Typed access; throw InvalidInput naming \p what when the type is wrong.
    bool toBool(const std::string& what = "value") const;
    double toNumber(const std::string& what = "value") const;
    const std::string& toString(const std::string& what = "value") const;
    const Array& toArray(const std::string& what = "value") const;
    const Object& toObject(const std::string& what = "value") const;
    Object& objectRef(); ///< converts null to an empty object
    Array& arrayRef();   ///< converts null to an empty array

    /// Object member access; nullptr when absent (or when this is not an object).
    const Value* find(const std::string& key) const;
    bool contains(const std::string& key) const { return find(key) != nullptr; }

    /// Convenience getters for parameter objects: the member \p key, or \p fallback if absent.
    /// Throw InvalidInput "<key> must be a number" etc. on a wrong type.
    double number(const std::string& key, double fallback) const;
    std::int64_t integer(const std::string& key, std::int64_t fallback) const;
    bool boolean(const std::string& key, bool fallback) const;
    std::string string(const std::string& key, const std::string& fallback) const;

    /// Compact canonical JSON text (sorted keys, shortest round-trip numbers).
    std::string toJson() const;
    /// Canonical JSON indented by two spaces per level, arrays of numbers kept on one line;
    /// what files for people to read (projects, species) are saved as. Ends without newline.
    std::string toPrettyJson() const;
    /// Parses JSON text; throws InvalidInput with line and column.
    static Value parseJson(const std::string& text, const std::string& fileName = {});
    /// Parses a command-line value: JSON if it parses, otherwise a plain string.
    static Value parseLoose(const std::string& text);

    /// 64-bit FNV-1a over toJson(): the cache key of a node's parameters.
    std::uint64_t hash() const;

    bool operator==(const Value& other) const { return mData == other.mData; }

private:
    std::variant<std::monostate, bool, double, std::string, Array, Object> mData;
};

} // namespace sylva
