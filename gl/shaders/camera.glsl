// The camera as shading sees it: the GLSL twin of Camera::to_eye (ref/scene/scene.cpp). In an
// orthographic view every view ray is parallel, so the direction to the eye is -forward everywhere.
uniform vec3 u_camera_position;
uniform vec3 u_camera_forward;  // unit
uniform int u_camera_orthographic;

vec3 to_eye(vec3 p) {
  return u_camera_orthographic != 0 ? -u_camera_forward : normalize(u_camera_position - p);
}
