# Run by scripts/peers/godot_driver.py inside Godot 3.2 (Debian godot3-server), issue 36:
#   godot3-server --no-window -s scripts/peers/godot_driver.gd -- IN.bin OUT.bin
# Every number goes both ways as a little-endian binary double (File.get_double / store_double):
# GDScript prints a float with 6 significant digits, so text would lose them.
#
# IN: u32 magic 0x44474243, u32 mode (1 = Curve2D, 2 = bezier track), f64 pass_usec, u32 passes.
#  mode 1: u32 cases; per case: u32 n points, n x (position x, y, in x, y, out x, y) f64 (handles
#          relative to their point, as Curve2D.add_point takes them), u32 intervals, their f64
#          bake_interval, u32 n_s, the f64 s, u32 n_spaced.
#  mode 2: u32 cases; per case: f64 x1, y1, x2, y2, u32 n, the n f64 times.
# OUT: u32 magic, pascal string Engine.get_version_info()["string"], then
#  mode 1: per case and interval: f64 length, n_s x (x, y) points, n_spaced x (x, y), f64 ns_build,
#          ns_length, ns_point.
#  mode 2: per case: the n f64 values, f64 ns_per_op.
#
# Curve2D: get_baked_length() (which bakes when the cache is dirty), interpolate_baked(offset) with
# its default cubic = false (linear between the baked points); the point at s is asked at
# min(s, baked length); spaced at k L / (n - 1), L the baked length. Setting bake_interval marks the
# cache dirty: ns_build times "bake_interval = v; get_baked_length()" (one bake), ns_length a
# get_baked_length() of a baked curve (its stored value), ns_point one interpolate_baked averaged
# over the s. Bezier track: an Animation with a TYPE_BEZIER track, key (0, 0) with out handle
# (x1, y1) and key (1, 1) with in handle (x2 - 1, y2 - 1); bezier_track_interpolate(track, t).
# Times: OS.get_ticks_usec around a loop whose count doubles until a pass lasts pass_usec, then the
# best of `passes` passes, divided by the calls (the GDScript loop's own cost included).
extends SceneTree

const MAGIC = 0x44474243

var pass_usec = 2000.0
var passes = 5


func _init():
	var args = OS.get_cmdline_args()
	var at = -1
	for i in range(args.size()):
		if args[i] == "--":
			at = i
	var paths = []
	if at >= 0:
		for i in range(at + 1, args.size()):
			paths.append(args[i])
	if paths.size() != 2:
		printerr("godot_driver.gd: expected -- IN.bin OUT.bin, got ", args)
		quit(2)
		return
	var inp = File.new()
	if inp.open(paths[0], File.READ) != OK:
		printerr("godot_driver.gd: cannot read ", paths[0])
		quit(2)
		return
	var out = File.new()
	if out.open(paths[1] + ".tmp", File.WRITE) != OK:
		printerr("godot_driver.gd: cannot write ", paths[1])
		quit(2)
		return
	if inp.get_32() != MAGIC:
		printerr("godot_driver.gd: ", paths[0], " is not the driver's input")
		quit(2)
		return
	var mode = inp.get_32()
	pass_usec = inp.get_double()
	passes = inp.get_32()
	out.store_32(MAGIC)
	out.store_pascal_string(Engine.get_version_info()["string"])
	if mode == 1:
		curves(inp, out)
	elif mode == 2:
		tracks(inp, out)
	else:
		printerr("godot_driver.gd: unknown mode ", mode)
		quit(2)
		return
	inp.close()
	out.close()
	var d = Directory.new()
	d.rename(paths[1] + ".tmp", paths[1])
	quit(0)


func read_doubles(f, n):
	var a = []
	for i in range(n):
		a.append(f.get_double())
	return a


func curves(inp, out):
	var cases = inp.get_32()
	for ci in range(cases):
		var c = Curve2D.new()
		var n = inp.get_32()
		for i in range(n):
			var v = read_doubles(inp, 6)
			c.add_point(Vector2(v[0], v[1]), Vector2(v[2], v[3]), Vector2(v[4], v[5]))
		var intervals = read_doubles(inp, inp.get_32())
		var s_list = read_doubles(inp, inp.get_32())
		var n_spaced = inp.get_32()
		for iv in intervals:
			c.bake_interval = iv
			var L = c.get_baked_length()
			out.store_double(L)
			for s in s_list:
				var p = c.interpolate_baked(min(s, L))
				out.store_double(p.x)
				out.store_double(p.y)
			for k in range(n_spaced):
				var sk = L if k == n_spaced - 1 else L * k / (n_spaced - 1)
				var p = c.interpolate_baked(sk)
				out.store_double(p.x)
				out.store_double(p.y)
			out.store_double(time_bake(c, iv))
			out.store_double(time_length(c))
			out.store_double(time_points(c, s_list, L))


# The bookkeeping of one timing loop (the timed loop itself stays inline in its caller, so that no
# function call is timed): while record(the pass's usec, operations per repetition) is true, time
# another pass of `count` repetitions; then `best` is the ns per operation.
class Best:
	var count = 1
	var best = -1.0
	var done = 0
	var pass_usec
	var passes

	func _init(pass_usec_, passes_):
		pass_usec = pass_usec_
		passes = passes_

	func record(dt, ops):
		if done == 0 and dt < pass_usec and count < (1 << 24):
			count *= 2
			return true
		var per = 1000.0 * dt / (count * max(1, ops))
		if best < 0 or per < best:
			best = per
		done += 1
		return done < passes


func time_bake(c, iv):
	var b = Best.new(pass_usec, passes)
	while true:
		var t0 = OS.get_ticks_usec()
		for i in b.count:
			c.bake_interval = iv
			c.get_baked_length()
		if not b.record(OS.get_ticks_usec() - t0, 1):
			return b.best


func time_length(c):
	var b = Best.new(pass_usec, passes)
	while true:
		var t0 = OS.get_ticks_usec()
		for i in b.count:
			c.get_baked_length()
		if not b.record(OS.get_ticks_usec() - t0, 1):
			return b.best


func time_points(c, s_list, L):
	if s_list.size() == 0:
		return 0.0
	var clamped = []
	for s in s_list:
		clamped.append(min(s, L))
	var b = Best.new(pass_usec, passes)
	while true:
		var t0 = OS.get_ticks_usec()
		for i in b.count:
			for s in clamped:
				c.interpolate_baked(s)
		if not b.record(OS.get_ticks_usec() - t0, clamped.size()):
			return b.best


func tracks(inp, out):
	var cases = inp.get_32()
	for ci in range(cases):
		var p = read_doubles(inp, 4)
		var times = read_doubles(inp, inp.get_32())
		var a = Animation.new()
		var tr = a.add_track(Animation.TYPE_BEZIER)
		a.bezier_track_insert_key(tr, 0.0, 0.0, Vector2(0, 0), Vector2(p[0], p[1]))
		a.bezier_track_insert_key(tr, 1.0, 1.0, Vector2(p[2] - 1.0, p[3] - 1.0), Vector2(0, 0))
		for t in times:
			out.store_double(a.bezier_track_interpolate(tr, t))
		var b = Best.new(pass_usec, passes)
		while true:
			var t0 = OS.get_ticks_usec()
			for i in b.count:
				for t in times:
					a.bezier_track_interpolate(tr, t)
			if not b.record(OS.get_ticks_usec() - t0, times.size()):
				break
		out.store_double(b.best)
