#include "cameras/lens_system.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace candela {

namespace {

// The medium in front of interface i (toward the scene): air before the first and around the
// stop (lens files give the stop an index of 0).
double etaBefore(const std::vector<LensInterface>& v, size_t i) {
  return (i == 0 || v[i - 1].isStop() || v[i - 1].eta == 0) ? 1.0 : v[i - 1].eta;
}
double etaBehind(const LensInterface& e) { return (e.isStop() || e.eta == 0) ? 1.0 : e.eta; }

// Snell's law in vector form: the unit incident direction d through a surface whose unit normal
// n faces the incident side, with eta = etaI / etaT. False under total internal reflection.
bool refract(const LensVector& d, const LensVector& n, double eta, LensVector* t) {
  double cosI = -d.dot(n);
  double sin2T = eta * eta * std::max(0.0, 1 - cosI * cosI);
  if (sin2T >= 1) return false;
  double cosT = std::sqrt(1 - sin2T);
  *t = d * eta + n * (eta * cosI - cosT);
  return true;
}

}  // namespace

LensSystem::LensSystem(std::vector<LensInterface> interfaces) : interfaces_(std::move(interfaces)) {
  if (interfaces_.empty()) throw std::runtime_error("a lens system needs at least one interface");
}

double LensSystem::frontZ() const {
  double z = 0;
  for (const LensInterface& e : interfaces_) z -= e.thickness;
  return z;
}

// Moves r to interface i (vertex at zVertex) and bends it there.
bool LensSystem::refractAt(size_t i, double zVertex, double etaI, double etaT, LensRay* r,
                           bool clipped) const {
  const LensInterface& e = interfaces_[i];
  double t;
  LensVector n;
  if (e.isStop()) {
    if (r->d.z == 0) return false;
    t = (zVertex - r->o.z) / r->d.z;
    if (!(t > 0)) return false;
  } else {
    // Sphere of radius |R| centred at zVertex + R. Of the two crossings the interface is the
    // one on the vertex's side of the centre (the cap the aperture cuts out), whichever way the
    // ray travels.
    double R = e.curvatureRadius;
    LensVector oc = r->o - LensVector{0, 0, zVertex + R};
    double a = r->d.dot(r->d), b = 2 * r->d.dot(oc), c = oc.dot(oc) - R * R;
    double disc = b * b - 4 * a * c;
    if (!(disc >= 0)) return false;
    // The cancellation-free pair of roots.
    double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double roots[2] = {q / a, q != 0 ? c / q : -b / (2 * a)};
    t = -1;
    for (double root : roots) {
      if (!(root > 0)) continue;
      double zRel = oc.z + root * r->d.z;  // hit z relative to the centre
      if (zRel * -R >= 0 && (t < 0 || root < t)) t = root;
    }
    if (t < 0) return false;
    n = (oc + r->d * t) * (1 / std::abs(R));
    if (n.dot(r->d) > 0) n = n * -1;
  }
  LensVector p = r->at(t);
  if (clipped && p.x * p.x + p.y * p.y > e.apertureRadius * e.apertureRadius) return false;
  r->o = p;
  if (e.isStop()) return true;
  LensVector d = r->d * (1 / r->d.length()), out;
  if (!refract(d, n, etaI / etaT, &out)) return false;
  r->d = out;
  return true;
}

bool LensSystem::traceFromFilm(const LensRay& in, LensRay* out, bool clipped) const {
  LensRay r = in;
  double z = 0;
  for (size_t k = interfaces_.size(); k-- > 0;) {
    z -= interfaces_[k].thickness;
    // Coming from the film the ray leaves the medium behind the interface.
    if (!refractAt(k, z, etaBehind(interfaces_[k]), etaBefore(interfaces_, k), &r, clipped))
      return false;
  }
  if (out) *out = r;
  return true;
}

bool LensSystem::traceFromScene(const LensRay& in, LensRay* out, bool clipped) const {
  LensRay r = in;
  double z = frontZ();
  for (size_t k = 0; k < interfaces_.size(); ++k) {
    if (!refractAt(k, z, etaBefore(interfaces_, k), etaBehind(interfaces_[k]), &r, clipped))
      return false;
    z += interfaces_[k].thickness;
  }
  if (out) *out = r;
  return true;
}

ThickLens LensSystem::thickLens() const {
  // A millionth of the smallest lens aperture or radius: paraxial to 1e-12, and far above
  // double precision's rounding.
  double scale = 1e-3;
  bool first = true;
  for (const LensInterface& e : interfaces_)
    if (!e.isStop()) {
      double s = std::min(e.apertureRadius, std::abs(e.curvatureRadius));
      scale = first ? s : std::min(scale, s);
      first = false;
    }
  const double h = 1e-6 * scale;
  // Where an exiting ray that entered parallel to the axis at height h crosses the axis (the
  // focal point) and where it meets the entering ray's line (the principal plane).
  auto cardinal = [&](const LensRay& exit, double* zFocal, double* zPrincipal) {
    if (!(std::abs(exit.d.x) > 0)) throw std::runtime_error("the lens does not focus");
    *zFocal = exit.at(-exit.o.x / exit.d.x).z;
    *zPrincipal = exit.at((h - exit.o.x) / exit.d.x).z;
  };
  ThickLens t;
  LensRay exit;
  if (!traceFromScene({{h, 0, frontZ() - 1}, {0, 0, 1}}, &exit, false))
    throw std::runtime_error("a paraxial ray from the scene does not pass the lens");
  cardinal(exit, &t.focalPointFilm, &t.principalFilm);
  if (!traceFromFilm({{h, 0, 1}, {0, 0, -1}}, &exit, false))
    throw std::runtime_error("a paraxial ray from the film does not pass the lens");
  cardinal(exit, &t.focalPointScene, &t.principalScene);
  t.focalLength = t.focalPointFilm - t.principalFilm;
  return t;
}

double LensSystem::filmDistanceFocusing(double focusDistance) const {
  // Moving the film away by delta (the lens toward -z) keeps H and H' a fixed L apart from the
  // object at z = -focusDistance: with s = distance from the object to H and s' = from H' to
  // the film, s + s' = L = principalScene + focusDistance - principalFilm, and the lens
  // equation 1/s + 1/s' = 1/f gives s'^2 - L s' + f L = 0. The smaller root is the image of a
  // distant object near the focal point (the larger one magnifies); then delta = s' +
  // principalFilm (H' sits at principalFilm - delta).
  ThickLens t = thickLens();
  double f = t.focalLength;
  if (!(f > 0))
    throw std::runtime_error("the lens diverges (focal length " + std::to_string(f) +
                             " m): it cannot focus");
  double L = t.principalScene + focusDistance - t.principalFilm;
  double disc = L * (L - 4 * f);
  if (!(L > 0) || !(disc >= 0))
    throw std::runtime_error(
        "no film position focuses at that distance (the lens's focal length "
        "is " +
        std::to_string(f * 1000) + " mm)");
  double sImage = 0.5 * (L - std::sqrt(disc));
  double delta = sImage + t.principalFilm;
  return filmDistance() + delta;
}

}  // namespace candela
