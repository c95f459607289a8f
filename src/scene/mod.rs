//! Scenes: the declarative description the parser produces, and the runtime form built from it.

pub mod atmosphere;
pub mod build;
pub mod children;
mod clip_hit;
pub mod csg_boxes;
pub mod csg_hit;
mod csg_members;
pub mod cull;
pub mod desc;
pub mod df3;
pub mod face_lanes;
pub mod faces;
pub mod focal;
pub mod gif;
pub mod height_image;
pub mod image;
pub mod image_pixels;
pub mod light;
pub mod light_group;
pub mod media;
pub mod mesh_camera;
pub mod mesh_triangles;
pub mod object;
pub mod pattern;
pub mod photon;
pub mod scratch;
pub mod shapes;
