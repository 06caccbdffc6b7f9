#include "ui/viewport/reducedtarget.h"

#include <algorithm>
#include <cmath>

namespace sylva::ui {

bool ReducedTarget::bind(QOpenGLFunctions_3_3_Core* gl, const QSize& full, float scale,
                         GLuint defaultFbo) {
    mGl = gl;
    const QSize size(std::max(1, int(std::lround(float(full.width()) * scale))),
                     std::max(1, int(std::lround(float(full.height()) * scale))));
    if (!mFbo || size != mSize) {
        release();
        mGl = gl;
        mGl->glGenFramebuffers(1, &mFbo);
        mGl->glGenRenderbuffers(1, &mColor);
        mGl->glGenRenderbuffers(1, &mDepth);
        mGl->glBindRenderbuffer(GL_RENDERBUFFER, mColor);
        mGl->glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.width(), size.height());
        mGl->glBindRenderbuffer(GL_RENDERBUFFER, mDepth);
        mGl->glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.width(),
                                   size.height());
        mGl->glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
        mGl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                       mColor);
        mGl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                       mDepth);
        mSize = size;
        if (mGl->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            release();
            gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFbo);
            return false;
        }
    }
    mGl->glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    mGl->glViewport(0, 0, mSize.width(), mSize.height());
    return true;
}

void ReducedTarget::blit(const QSize& full, GLuint defaultFbo) {
    mGl->glBindFramebuffer(GL_READ_FRAMEBUFFER, mFbo);
    mGl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFbo);
    mGl->glBlitFramebuffer(0, 0, mSize.width(), mSize.height(), 0, 0, full.width(), full.height(),
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
    mGl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFbo);
    mGl->glViewport(0, 0, full.width(), full.height());
}

void ReducedTarget::release() {
    if (mGl) {
        if (mFbo) mGl->glDeleteFramebuffers(1, &mFbo);
        if (mColor) mGl->glDeleteRenderbuffers(1, &mColor);
        if (mDepth) mGl->glDeleteRenderbuffers(1, &mDepth);
    }
    mFbo = mColor = mDepth = 0;
    mSize = {};
}

} // namespace sylva::ui
