// The positive control of device.no_soft_float_helpers: built with the device flags, this floating
// point arithmetic must become soft-float helper calls, which the check has to find. If it finds
// none here, the check is blind (wrong nm, wrong pattern, hardware floating point) and fails.
float octopointSoftFloatControl(float scale, int value) {
  return scale * static_cast<float>(value);
}
double octopointSoftDoubleControl(double scale, int value) { return scale * value; }
