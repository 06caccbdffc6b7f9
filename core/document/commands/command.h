#pragma once

#include <functional>

#include <QCoreApplication>
#include <QUndoCommand>

#include "document/document.h"

namespace sylva::doc::cmd {

/// Merge ids of the commands that merge while an edit is in progress (a drag, a slider, a burst
/// of typing): one enum so that no two command types share an id.
enum MergeId : int {
    kMergeTree = 1,
    kMergeSpecies,
    kMergeObstacle,
    kMergeDomain,
    kMergeSettings,
    kMergeBranchEdits,
};

/// "Change a value" in the Tiled/Glaxnimate manner: the document's value at a key (a tree id, a
/// list index) goes from old to new through a setter. While not committed (a drag in progress)
/// the next change of the same key merges into this step; a change that ends where it began
/// is obsolete and leaves no step.
template <typename Key, typename T> class ChangeValue : public QUndoCommand {
public:
    using Setter = std::function<void(Document&, const Key&, const T&)>;
    ChangeValue(Document& doc, int mergeId, Key key, T oldValue, T newValue, bool commit,
                Setter set, const QString& label)
        : QUndoCommand(label), mDoc(doc), mMergeId(mergeId), mKey(std::move(key)),
          mOld(std::move(oldValue)), mNew(std::move(newValue)), mCommitted(commit),
          mSet(std::move(set)) {
        setObsolete(mOld == mNew);
    }
    void undo() override { mSet(mDoc, mKey, mOld); }
    void redo() override { mSet(mDoc, mKey, mNew); }
    int id() const override { return mMergeId; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = dynamic_cast<const ChangeValue*>(other);
        if (!o || mCommitted || !(o->mKey == mKey)) return false;
        mNew = o->mNew;
        mCommitted = o->mCommitted;
        setObsolete(mOld == mNew);
        return true;
    }

private:
    Document& mDoc;
    int mMergeId;
    Key mKey;
    T mOld, mNew;
    bool mCommitted;
    Setter mSet;
};

/// Inserts (redo) or removes (undo) an element of one of the document's lists; with `remove`
/// the other way round.
template <typename T> class ListEdit : public QUndoCommand {
public:
    using Insert = std::function<void(Document&, int, const T&)>;
    using Remove = std::function<void(Document&, int)>;
    ListEdit(Document& doc, bool remove, int index, T value, Insert insert, Remove removeAt,
             const QString& label)
        : QUndoCommand(label), mDoc(doc), mRemove(remove), mIndex(index), mValue(std::move(value)),
          mInsert(std::move(insert)), mRemoveAt(std::move(removeAt)) {}
    void undo() override { mRemove ? mInsert(mDoc, mIndex, mValue) : mRemoveAt(mDoc, mIndex); }
    void redo() override { mRemove ? mRemoveAt(mDoc, mIndex) : mInsert(mDoc, mIndex, mValue); }

private:
    Document& mDoc;
    bool mRemove;
    int mIndex;
    T mValue;
    Insert mInsert;
    Remove mRemoveAt;
};

} // namespace sylva::doc::cmd
