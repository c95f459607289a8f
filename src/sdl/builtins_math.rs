//! The float and vector built-ins of the scene language (manual 3.3.1.5.4 and 3.3.1.6.5),
//! built-in float identifiers (`pi`, `clock`, ...), `seed`/`rand`, the object queries
//! (`inside`, `trace`, `min_extent`, `max_extent`) and calls of user-defined functions.
//!
//! Domain errors follow POV-Ray 3.7 as measured with its binary: `sqrt`, `ln` and `log` of
//! numbers out of range, `pow(0,0)` and `atan2(0,0)` stop parsing; `asin`/`acos` outside
//! [-1,1] warn and clamp; `int`, `div` and the bitwise functions convert through a C `int`, so
//! values beyond ±2^31 (and NaN) become -2^31 as they do on x86.

use std::rc::Rc;
use std::sync::Arc;

use crate::func::{FnValue, Function};
use crate::math::{DVec3, Ray};

use super::built_objects::{Built, Key, ObjectArg};
use super::lexer::{Sym, Tok};
use super::parser::{PResult, Parser};
use super::source::Span;
use super::value::Value;

/// What stands in the arguments for an object argument answered by `ObjectArg::Kept`: only
/// `runtime_object` reads that argument's value, and it does not for a kept object.
const KEPT_PLACEHOLDER: Value = Value::Float(0.0);

/// A kept object and the span of the identifier that named it.
type KeptArg = (Built, Span);

/// POV-Ray's random streams: `state = state * 1812433253 + 12345 (mod 2^32)` and the number
/// returned is `state / (2^32 - 1)`, so both 0 and 1 can occur. `seed(S)` starts a stream
/// with state `(int)S` and returns the stream's index.
///
/// Derived by experiment with the 3.7 binary: the first value of `seed(0)` printed with 17
/// digits was 2.87429429658e-6 = 12345 / 4294967295, which fixed the increment and divisor;
/// the next values of that stream times 4294967295 were integers, and the multiplier solved
/// from two consecutive states predicted all further ones. Checked on 3000 values each of the
/// seeds 0, 1, 12345, -7, 574647 and 2147483647 (largest error 7e-18), and on
/// `seed(1.7)` = `seed(1)`, `seed(-2.5)` = `seed(-2)` and seeds of 2^31 or more (all equal
/// to `seed(-2^31)`). `rand(I)` uses stream `(int)I`; a copy of the identifier shares the
/// stream, and an index no `seed` returned is an error.
pub(super) fn lcg_next(state: &mut u32) -> f64 {
    *state = state.wrapping_mul(1_812_433_253).wrapping_add(12_345);
    *state as f64 / u32::MAX as f64
}

/// A float converted to a C `int` as POV-Ray does on x86: truncation, and -2^31 for anything
/// that does not fit (including NaN and infinities).
pub(super) fn c_int(x: f64) -> i32 {
    let t = x.trunc();
    if (-2_147_483_648.0..=2_147_483_647.0).contains(&t) {
        t as i32
    } else {
        i32::MIN
    }
}

/// Days since 2000-01-01 00:00 UTC, POV-Ray's `now`.
fn days_since_2000() -> f64 {
    const EPOCH_2000: f64 = 946_684_800.0;
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs_f64())
        .unwrap_or(EPOCH_2000);
    (secs - EPOCH_2000) / 86_400.0
}

/// Bounds as POV-Ray reports them: single precision, unbounded sides at ±1e10.
fn extent(v: f64) -> f64 {
    (v.clamp(-1e10, 1e10) as f32) as f64
}

/// The maths built-ins, sorted: looked up by binary search for every call in a loop.
/// trace() calls after which a scene is warned that last-bit differences may add up.
const TRACE_CALLS_WARNED: u32 = 1000;

const NAMES: &[&str] = &[
    "abs",
    "acos",
    "acosh",
    "asin",
    "asinh",
    "atan",
    "atan2",
    "atanh",
    "bitwise_and",
    "bitwise_or",
    "bitwise_xor",
    "ceil",
    "cos",
    "cosh",
    "degrees",
    "div",
    "exp",
    "floor",
    "inside",
    "int",
    "ln",
    "log",
    "max",
    "max_extent",
    "min",
    "min_extent",
    "mod",
    "pow",
    "radians",
    "rand",
    "seed",
    "select",
    "sin",
    "sinh",
    "sqrt",
    "tan",
    "tanh",
    "trace",
    "vaxis_rotate",
    "vcross",
    "vdot",
    "vlength",
    "vnormalize",
    "vrotate",
    "vturbulence",
];

/// A built-in call's arguments with their spans; up to four without a heap allocation (a
/// loop calling `mod(I, 100)` a million times allocated and freed a `Vec` for each).
pub(super) type Args = smallvec::SmallVec<[(Value, Span); 4]>;

/// Whether `name` is one of `NAMES`: one hash and one comparison, where a binary search made
/// half a dozen string comparisons for every `mod(I, 100)` of a loop.
pub(super) fn is_math_builtin(name: &str) -> bool {
    static SET: std::sync::OnceLock<rustc_hash::FxHashSet<&'static str>> =
        std::sync::OnceLock::new();
    SET.get_or_init(|| NAMES.iter().copied().collect())
        .contains(name)
}

impl Parser {
    /// The built-in float identifiers: constants and the animation variables.
    pub(super) fn builtin_float_ident(&self, name: &str) -> Option<f64> {
        let o = &self.options;
        Some(match name {
            "pi" => std::f64::consts::PI,
            // Not in POV-Ray 3.7 (it came with 3.8); kept because scenes written for either
            // parse the same when they do not declare it themselves.
            "tau" => std::f64::consts::TAU,
            "true" | "on" | "yes" => 1.0,
            "false" | "off" | "no" => 0.0,
            "image_width" => o.image_width as f64,
            "image_height" => o.image_height as f64,
            "clock" => o.clock,
            "clock_delta" => o.clock_delta,
            "clock_on" => o.clock_on as u8 as f64,
            "frame_number" => o.frame_number as f64,
            "initial_frame" => o.initial_frame as f64,
            "final_frame" => o.final_frame as f64,
            "initial_clock" => o.initial_clock,
            "final_clock" => o.final_clock,
            "version" => self.scene.version.unwrap_or(3.7),
            "now" => days_since_2000(),
            _ => return None,
        })
    }

    /// Arguments of a built-in call, after its name: `( expr, expr, ... )`.
    pub(super) fn call_args(&mut self, name: &str) -> PResult<Args> {
        let mut args = Args::new();
        self.call_args_into(name, false, &mut args)?;
        Ok(args)
    }

    /// `call_args` into `args`, and with `first_ident` the identifier the first argument
    /// starts with (the object of `inside(Obj, P)`, to find what was built from it before).
    /// The arguments are filled in place: returning them through a `Result` copied the
    /// 300-byte `Args` for every `mod(I, 100)` of a loop.
    fn call_args_into(
        &mut self,
        name: &str,
        first_ident: bool,
        args: &mut Args,
    ) -> PResult<Option<ObjectArg>> {
        // The error context is formatted only on an error: this runs for every `mod(I, 100)`
        // of a million-iteration loop.
        self.expect_sym_with(Sym::LParen, || format!("after the function name {name}"))?;
        if self.eat_sym(Sym::RParen)? {
            return Ok(None);
        }
        let mut key = None;
        let mut ident = None;
        if first_ident {
            match self.kept_object_arg()? {
                (_, Some((built, s))) => {
                    args.push((KEPT_PLACEHOLDER, s));
                    key = Some(ObjectArg::Kept(built));
                    if self.eat_sym(Sym::RParen)? {
                        return Ok(key);
                    }
                    self.expect_sym_with(Sym::Comma, || {
                        format!("between the arguments of {name}")
                    })?;
                }
                (n, None) => ident = n,
            }
        }
        loop {
            let s = self.next_span()?;
            let v = self.with_rel(false, |p| p.parse_expr())?;
            args.push((v, s));
            if let Some(n) = ident.take() {
                key = self.object_key(n).map(ObjectArg::Read);
            }
            if self.eat_sym(Sym::RParen)? {
                return Ok(key);
            }
            self.expect_sym_with(Sym::Comma, || format!("between the arguments of {name}"))?;
        }
    }

    /// A maths built-in call, or `None` when `name` is not one of them.
    pub(super) fn math_builtin(&mut self, name: &str, span: Span) -> Option<PResult<Value>> {
        if !is_math_builtin(name) {
            return None;
        }
        Some(if name == "trace" {
            self.trace_call()
        } else {
            let object_arg = matches!(name, "inside" | "min_extent" | "max_extent");
            let mut args = Args::new();
            self.call_args_into(name, object_arg, &mut args)
                .and_then(|ident| self.math_call(name, span, &args, ident))
        })
    }

    fn arg_float(&self, name: &str, a: &(Value, Span)) -> PResult<f64> {
        match &a.0 {
            Value::Float(f) => Ok(*f),
            Value::Color(c) => Ok(c.rgb.x),
            o => Err(self.error_at(
                a.1,
                format!("{name} needs a float here, found a {}", o.type_name()),
            )),
        }
    }

    fn arg_vector(&self, name: &str, a: &(Value, Span)) -> PResult<DVec3> {
        self.vector_of(&a.0, a.1, &format!("{name} needs a vector here"))
    }

    /// `ident`: where the first argument was read from, if it is an identifier.
    fn math_call(
        &mut self,
        name: &str,
        span: Span,
        args: &[(Value, Span)],
        mut ident: Option<ObjectArg>,
    ) -> PResult<Value> {
        let arity: &[usize] = match name {
            "atan2" | "div" | "mod" | "pow" | "vdot" | "vcross" | "vrotate" | "inside" => &[2],
            "vaxis_rotate" => &[3],
            "vturbulence" => &[4],
            "select" => &[3, 4],
            "atan" => &[1, 2],
            "min" | "max" | "bitwise_and" | "bitwise_or" | "bitwise_xor" => &[],
            _ => &[1],
        };
        if arity.is_empty() && args.is_empty() {
            return Err(self.error_at(span, format!("{name} needs at least one argument")));
        }
        if !arity.is_empty() && !arity.contains(&args.len()) {
            let want = arity
                .iter()
                .map(|n| n.to_string())
                .collect::<Vec<_>>()
                .join(" or ");
            return Err(self.error_at(
                span,
                format!("{name} takes {want} argument(s), {} given", args.len()),
            ));
        }
        let fl = |p: &Parser, i: usize| p.arg_float(name, &args[i]);
        let ve = |p: &Parser, i: usize| p.arg_vector(name, &args[i]);
        let all = |p: &Parser| -> PResult<Vec<f64>> { (0..args.len()).map(|i| fl(p, i)).collect() };
        let f = |x: f64| Ok(Value::Float(x));
        match name {
            "abs" => f(fl(self, 0)?.abs()),
            "sin" => f(fl(self, 0)?.sin()),
            "cos" => f(fl(self, 0)?.cos()),
            "tan" => f(fl(self, 0)?.tan()),
            "sinh" => f(fl(self, 0)?.sinh()),
            "cosh" => f(fl(self, 0)?.cosh()),
            "tanh" => f(fl(self, 0)?.tanh()),
            "asinh" => f(fl(self, 0)?.asinh()),
            "acosh" => f(fl(self, 0)?.acosh()),
            "atanh" => f(fl(self, 0)?.atanh()),
            "exp" => f(fl(self, 0)?.exp()),
            "floor" => f(fl(self, 0)?.floor()),
            "ceil" => f(fl(self, 0)?.ceil()),
            "int" => f(c_int(fl(self, 0)?) as f64),
            "radians" => f(fl(self, 0)?.to_radians()),
            "degrees" => f(fl(self, 0)?.to_degrees()),
            "asin" | "acos" => {
                let x = fl(self, 0)?;
                if !(-1.0..=1.0).contains(&x) {
                    self.warn(
                        span,
                        format!(
                            "domain error in {name}({x}): taken as {name}({})",
                            x.clamp(-1.0, 1.0)
                        ),
                    );
                }
                let x = x.clamp(-1.0, 1.0);
                f(if name == "asin" { x.asin() } else { x.acos() })
            }
            "sqrt" | "ln" | "log" => {
                let x = fl(self, 0)?;
                if x < 0.0 || (x == 0.0 && name != "sqrt") {
                    return Err(
                        self.error_at(span, format!("{name} of a number out of its domain: {x}"))
                    );
                }
                f(match name {
                    "sqrt" => x.sqrt(),
                    "ln" => x.ln(),
                    _ => x.log10(),
                })
            }
            "atan" if args.len() == 1 => f(fl(self, 0)?.atan()),
            "atan" | "atan2" => {
                let (a, b) = (fl(self, 0)?, fl(self, 1)?);
                if a == 0.0 && b == 0.0 {
                    return Err(self.error_at(span, format!("{name}(0, 0) has no angle")));
                }
                f(a.atan2(b))
            }
            "pow" => {
                let (a, b) = (fl(self, 0)?, fl(self, 1)?);
                if a == 0.0 && b == 0.0 {
                    return Err(self.error_at(span, "pow(0, 0) is a domain error in POV-Ray"));
                }
                f(a.powf(b))
            }
            "div" => f(c_int(fl(self, 0)? / fl(self, 1)?) as f64),
            "mod" => {
                let (a, b) = (fl(self, 0)?, fl(self, 1)?);
                if b == 0.0 {
                    self.warn(span, "mod(A, 0) is not a number (POV-Ray gives nan too)");
                }
                f(a % b)
            }
            "min" => f(all(self)?.into_iter().fold(f64::INFINITY, f64::min)),
            "max" => f(all(self)?.into_iter().fold(f64::NEG_INFINITY, f64::max)),
            "bitwise_and" | "bitwise_or" | "bitwise_xor" => {
                let v = all(self)?;
                let mut acc = c_int(v[0]);
                for x in &v[1..] {
                    let x = c_int(*x);
                    acc = match name {
                        "bitwise_and" => acc & x,
                        "bitwise_or" => acc | x,
                        _ => acc ^ x,
                    };
                }
                f(acc as f64)
            }
            "select" => {
                let v = all(self)?;
                f(if v[0] < 0.0 {
                    v[1]
                } else if v.len() == 3 || v[0] == 0.0 {
                    v[2]
                } else {
                    v[3]
                })
            }
            "vdot" => f(ve(self, 0)?.dot(ve(self, 1)?)),
            "vlength" => f(ve(self, 0)?.length()),
            "vcross" => Ok(Value::vec3(ve(self, 0)?.cross(ve(self, 1)?))),
            "vnormalize" => {
                let v = ve(self, 0)?;
                if v == DVec3::ZERO {
                    self.warn(span, "normalizing a zero-length vector gives <0,0,0>");
                    return Ok(Value::vec3(v));
                }
                Ok(Value::vec3(v.normalize()))
            }
            "vrotate" => Ok(Value::vec3(
                crate::math::Transform::rotate(ve(self, 1)?).point(ve(self, 0)?),
            )),
            "vaxis_rotate" => {
                let (p, axis, ang) = (ve(self, 0)?, ve(self, 1)?, fl(self, 2)?);
                if axis == DVec3::ZERO {
                    return Err(self.error_at(
                        args[1].1,
                        "vaxis_rotate needs a non-zero axis (POV-Ray returns nan)",
                    ));
                }
                // POV-Ray's angle sense is the left-handed one, which is glam's right-handed
                // rotation with the same sign (see math::Transform::rotate).
                let m = glam::DMat3::from_axis_angle(axis.normalize(), ang.to_radians());
                Ok(Value::vec3(m * p))
            }
            "vturbulence" => {
                // vturbulence(lambda, omega, octaves, point): POV-Ray's own vector turbulence
                // (measured, see render::noise and docs/noise.md).
                let (lambda, omega, octaves) = (fl(self, 0)?, fl(self, 1)?, fl(self, 2)?);
                let p = ve(self, 3)?;
                let octaves = (octaves as i64).clamp(1, 10) as u32;
                Ok(Value::vec3(crate::render::noise::turbulence_vec(
                    p, octaves, omega, lambda, 2,
                )))
            }
            "seed" => {
                let s = c_int(fl(self, 0)?) as u32;
                self.rand_streams.push(s);
                f((self.rand_streams.len() - 1) as f64)
            }
            "rand" => {
                let i = c_int(fl(self, 0)?);
                match usize::try_from(i)
                    .ok()
                    .and_then(|i| self.rand_streams.get_mut(i))
                {
                    Some(s) => f(lcg_next(s)),
                    None => Err(self.error_at(
                        args[0].1,
                        format!(
                            "rand({i}): no random stream has this number; make one with seed()"
                        ),
                    )),
                }
            }
            "inside" => {
                let p = ve(self, 1)?;
                let Some(obj) = self.runtime_object(name, &args[0], ident.take())? else {
                    return f(0.0);
                };
                f(obj.inside(p) as u8 as f64)
            }
            "min_extent" | "max_extent" => {
                let Some(obj) = self.runtime_object(name, &args[0], ident.take())? else {
                    return Ok(Value::vec3(DVec3::ZERO));
                };
                let b = obj.bounds;
                let v = if name == "min_extent" { b.min } else { b.max };
                Ok(Value::vec3(DVec3::new(
                    extent(v.x),
                    extent(v.y),
                    extent(v.z),
                )))
            }
            _ => Err(self.error_at(
                span,
                format!("the function {name} is not supported by lancer yet"),
            )),
        }
    }

    /// The object an identifier argument holds, built as the renderer would build it; `None`,
    /// with a warning, when nothing in it is geometry lancer renders yet (a `blob`):
    /// the caller then answers as for an empty object, so the scene still parses.
    ///
    /// `ident` is the identifier the argument was read from, if it was one: what was built
    /// from it is kept (`built_objects`) and answers the next call on it, until it changes.
    fn runtime_object(
        &mut self,
        name: &str,
        a: &(Value, Span),
        arg: Option<ObjectArg>,
    ) -> PResult<Built> {
        let key = match arg {
            Some(ObjectArg::Kept(built)) => {
                if built.is_none() {
                    self.warn_no_geometry(name, a.1);
                }
                return Ok(built);
            }
            Some(ObjectArg::Read(key)) => Some(key),
            None => None,
        };
        let built = self.build_runtime_object(name, a)?;
        if let Some(key) = key {
            self.built_objects.insert(key, built.clone());
        }
        Ok(built)
    }

    /// Before an object argument: the identifier it starts with, and when the object built
    /// from that identifier is kept, that object and the identifier's span, the identifier
    /// then read without copying its description (a union of 100 spheres copied and dropped
    /// per call was a third of a loop of `trace` calls).
    fn kept_object_arg(&mut self) -> PResult<(Option<Rc<str>>, Option<KeptArg>)> {
        let Some(name) = self.peek_ident()? else {
            return Ok((None, None));
        };
        let kept = self
            .object_key(name.clone())
            .and_then(|key| self.built_objects.get(&key));
        let Some(built) = kept else {
            return Ok((Some(name), None));
        };
        let t = self.next_tok()?;
        // As reading it in an expression would: counts as a use of the identifier.
        let _ = self.lookup(&name);
        Ok((Some(name), Some((built, t.span))))
    }

    /// Where the argument just read from identifier `name` came from, when `name` holds an
    /// object itself: not a by-reference alias nor an array, whose writes go elsewhere.
    fn object_key(&self, name: Rc<str>) -> Option<Key> {
        let scope = (0..self.scopes.len())
            .rev()
            .find(|&i| self.scopes[i].contains_key(&name))?;
        matches!(self.scopes[scope].get(&name), Some(Value::Object(_))).then(|| Key {
            name,
            scope,
            generation: self.built_objects.generation(),
        })
    }

    fn warn_no_geometry(&mut self, name: &str, span: Span) {
        self.warn(
            span,
            format!("{name}: this object has no geometry lancer renders yet; answering as for an empty object (POV-Ray's answer will differ)"),
        );
    }

    fn build_runtime_object(&mut self, name: &str, a: &(Value, Span)) -> PResult<Built> {
        let Value::Object(desc) = &a.0 else {
            return Err(self.error_at(
                a.1,
                format!(
                    "{name} needs an object identifier, found a {}",
                    a.0.type_name()
                ),
            ));
        };
        let mut scene = super::default_scene();
        scene.objects.push((**desc).clone());
        scene.global.assumed_gamma = Some(1.0);
        let mut built = crate::scene::build::build(&scene, 1, 1).scene;
        match built.objects.pop() {
            Some(o) if built.objects.is_empty() => Ok(Some(Rc::new(o))),
            _ => {
                self.warn_no_geometry(name, a.1);
                Ok(None)
            }
        }
    }

    /// `trace(Object, Start, Direction [, NormalIdentifier])`.
    fn trace_call(&mut self) -> PResult<Value> {
        self.expect_sym(Sym::LParen, "after trace")?;
        let mut args = Vec::new();
        let (ident, kept) = self.kept_object_arg()?;
        let mut key = None;
        if let Some((built, s)) = kept {
            args.push((KEPT_PLACEHOLDER, s));
            key = Some(ObjectArg::Kept(built));
        }
        for i in args.len()..3 {
            if i > 0 {
                self.expect_sym(Sym::Comma, "between the arguments of trace")?;
            }
            let s = self.next_span()?;
            args.push((self.with_rel(false, |p| p.parse_expr())?, s));
            if i == 0 {
                key = ident
                    .clone()
                    .and_then(|n| self.object_key(n))
                    .map(ObjectArg::Read);
            }
        }
        let mut normal_var = None;
        if self.eat_sym(Sym::Comma)? {
            let t = self.next_tok()?;
            match &t.tok {
                Tok::Ident(n) if matches!(self.lookup(n), Some(Value::Vector(..))) => {
                    normal_var = Some(n.clone())
                }
                _ => {
                    return Err(self.error_at(
                        t.span,
                        format!("trace's fourth argument must be a declared vector identifier (it receives the normal), found {}", t.tok),
                    ))
                }
            }
        }
        self.expect_sym(Sym::RParen, "to close trace")?;
        let start = self.arg_vector("trace", &args[1])?;
        let dir = self.arg_vector("trace", &args[2])?;
        if dir == DVec3::ZERO {
            return Err(self.error_at(args[2].1, "trace needs a non-zero direction"));
        }
        let obj = self.runtime_object("trace", &args[0], key)?;
        self.trace_calls += 1;
        if self.trace_calls == TRACE_CALLS_WARNED {
            // Measured (language/tracevines): lancer's trace() answers agree with POV-Ray's to
            // ~1e-10, not to the last bit; vines grown by feeding each answer into the next
            // call part after ~80 steps and end up elsewhere.
            self.warn(args[0].1, format!("'trace' is not supported by lancer yet: its answers agree with POV-Ray's to about 1e-10, not to the last bit, and this scene calls it {TRACE_CALLS_WARNED} times or more; where each answer feeds the next (vines, growth) the shapes will drift apart"));
        }
        let ray = Ray::new(start, dir.normalize());
        let mut scratch = crate::scene::object::Scratch::default();
        let hit = obj
            .as_ref()
            .and_then(|o| o.first_hit(&ray, f64::INFINITY, &mut scratch));
        let (point, normal) = match hit {
            Some(h) => {
                let p = ray.at(h.t);
                (p, h.obj.normal(p, &h))
            }
            None => (DVec3::ZERO, DVec3::ZERO),
        };
        if let Some(n) = normal_var {
            self.assign_var(n, Value::vec3(normal), false)?;
        }
        Ok(Value::vec3(point))
    }

    /// `F(a, b, ...)` for a declared function `F`: floats in, a float or vector out.
    pub(super) fn call_function(
        &mut self,
        name: &str,
        func: &Arc<Function>,
        span: Span,
    ) -> PResult<Value> {
        let args = self.call_args(name)?;
        if let Some(why) = &func.unsupported {
            // As for any feature lancer lacks: a warning naming it, and a neutral value so the
            // scene still parses (POV-Ray's picture will differ where the value matters).
            self.unsupported_now(&format!("{why} ({name} gives 0 here)"), span);
            return Ok(Value::Float(0.0));
        }
        if let Some(n) = func.arity() {
            if args.len() != n {
                return Err(self.error_at(
                    span,
                    format!(
                        "the function {name} takes {n} argument(s), {} given",
                        args.len()
                    ),
                ));
            }
        }
        let vals = args
            .iter()
            .map(|a| self.arg_float(name, a))
            .collect::<PResult<Vec<f64>>>()?;
        Ok(match func.call(&vals) {
            FnValue::Float(x) => Value::Float(x),
            FnValue::Vector(v) => Value::vec3(v),
            FnValue::Components(c, n) => Value::Vector(c, n),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_names_are_sorted_and_found() {
        assert!(NAMES.windows(2).all(|w| w[0] < w[1]));
        assert!(NAMES.iter().all(|n| is_math_builtin(n)));
        assert!(!is_math_builtin("sphere") && !is_math_builtin("Mod"));
    }

    /// `parse_ident_value` tries the maths built-ins before the other built-in identifiers
    /// (string functions, constants, `x`, `rgb`, ...), which is right only while no name is
    /// both.
    #[test]
    fn maths_names_are_no_other_builtin_identifier() {
        let others = [
            "dimensions",
            "dimension_size",
            "defined",
            "str",
            "vstr",
            "substr",
            "strupr",
            "strlwr",
            "strlen",
            "str_len",
            "strcmp",
            "val",
            "asc",
            "chr",
            "concat",
            "file_exists",
            "input_file_name",
            "datetime",
            "pi",
            "tau",
            "true",
            "on",
            "yes",
            "false",
            "off",
            "no",
            "image_width",
            "image_height",
            "clock",
            "clock_delta",
            "clock_on",
            "frame_number",
            "initial_frame",
            "final_frame",
            "initial_clock",
            "final_clock",
            "version",
            "now",
            "x",
            "y",
            "z",
            "t",
            "u",
            "v",
            "function",
            "color",
            "colour",
            "rgb",
            "rgbf",
            "rgbt",
            "rgbft",
            "srgb",
            "srgbf",
            "srgbt",
            "srgbft",
            "red",
            "green",
            "blue",
            "filter",
            "transmit",
        ];
        assert!(others.iter().all(|n| !is_math_builtin(n)));
    }

    #[test]
    fn c_int_saturates_to_int_min_like_x86() {
        assert_eq!(c_int(-2.7), -2);
        assert_eq!(c_int(1e20), i32::MIN);
        assert_eq!(c_int(-1e20), i32::MIN);
        assert_eq!(c_int(f64::NAN), i32::MIN);
        assert_eq!(c_int(2147483647.9), i32::MAX);
    }

    #[test]
    fn lcg_first_values_of_seed_zero() {
        let mut s = 0u32;
        assert!((lcg_next(&mut s) - 0.00000287429429658).abs() < 1e-17);
        assert!((lcg_next(&mut s) - 0.46656368450880137).abs() < 1e-16);
    }
}
