using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced): seeded worlds for the body.

/// <summary>
/// One seeded world for the body: cells built with <see cref="CellBuilder"/> into an engine, and the
/// same cells' walls handed to a <see cref="ReferenceBody"/> (placed by the reference itself from the
/// cells' own definitions). Floors are flat at <see cref="FloorZ"/>; movers start in <see cref="Areas"/>.
/// </summary>
internal sealed class BodyCourse
{
    public required string Name { get; init; }

    public required PhysicsEngine Engine { get; init; }

    public required uint LandblockId { get; init; }

    /// <summary>"global" (<c>new PhysicsEngine()</c>) or "centred" (<c>new PhysicsEngine(landblockId)</c>).</summary>
    public required string Frame { get; init; }

    /// <summary>The landblock's origin in the engine's world frame.</summary>
    public required Vector3 Origin { get; init; }

    public required ReferenceBody Reference { get; init; }

    /// <summary>The floors' Z (landblock-local and world alike).</summary>
    public required float FloorZ { get; init; }

    /// <summary>Where movers may start: a cell and a rectangle of its cell-local floor.</summary>
    public required List<(uint Cell, Frame Frame, Vector2 Min, Vector2 Max)> Areas { get; init; }

    /// <summary>Landblock-local double XY of a world position (exact: the origin is a multiple of 192).</summary>
    public ReferenceBody.Vec2 Local(Vector3 world) => new((double)world.X - Origin.X, (double)world.Y - Origin.Y);

    /// <summary>The XY of a world position in a cell's frame (the cell turned about Z only), as <c>float</c>.</summary>
    public Vector2 CellLocal(Frame frame, Vector3 world)
    {
        ReferenceBody.Vec2 local = Local(world);
        Quaternion q = Quaternion.Normalize(frame.Orientation);
        Vector3 back = Vector3.Transform(new Vector3((float)local.X - frame.Origin.X, (float)local.Y - frame.Origin.Y, 0), Quaternion.Conjugate(q));
        return new Vector2(back.X, back.Y);
    }

    /// <summary>
    /// A start in one of the areas at least <paramref name="clearance"/> from every wall in the body's
    /// band, settled on the floor by a zero move; null if none was found in 200 tries.
    /// </summary>
    public (Vector3 Position, uint Cell)? RandomStart(Random random, MoverBody body, float step, float clearance)
    {
        var options = new MovementOptions { Body = body };
        for (int attempt = 0; attempt < 200; attempt++)
        {
            (uint cell, Frame frame, Vector2 min, Vector2 max) = Areas[random.Next(Areas.Count)];
            var local = new Vector3(min.X + (random.NextSingle() * (max.X - min.X)), min.Y + (random.NextSingle() * (max.Y - min.Y)), 0f);
            ReferenceBody.Vec3 placed = ReferenceBody.Place(frame, local);
            var world = new Vector3((float)(Origin.X + placed.X), (float)(Origin.Y + placed.Y), FloorZ);
            ResolveResult settled = Engine.Resolve(world, cell, Vector3.Zero, step, options);
            if (settled.CellId != cell || !settled.IsOnGround)
            {
                continue;
            }

            double zLow = settled.Position.Z + step, zHigh = settled.Position.Z + body.Height;
            if (Reference.Clearance(Local(settled.Position), zLow, zHigh) >= body.Radius + clearance)
            {
                return (settled.Position, cell);
            }
        }

        return null;
    }
}

/// <summary>Builds seeded <see cref="BodyCourse"/>s of each kind.</summary>
internal static class BodyCourses
{
    public enum Kind
    {
        /// <summary>A rectangular room.</summary>
        Room,

        /// <summary>A long narrow room.</summary>
        Corridor,

        /// <summary>An L-shaped room: five convex-to-the-inside corners and one reflex (convex) corner.</summary>
        Corners,

        /// <summary>Two rooms sharing a zero-thickness wall with a doorway (portals both ways).</summary>
        Doorway,

        /// <summary>Two rooms joined through a 0.4 m door cell, as the real cottage's doors are.</summary>
        DoorCell,

        /// <summary>A room with free-standing zero-thickness walls, a pillar, a parapet, a curb and a beam.</summary>
        ThinWalls,

        /// <summary>A room closed off in two by a full-height partition of zero thickness at cell-local x = w/2; movers start west of it.</summary>
        Partition,
    }

    /// <summary>Wall height in every course, metres.</summary>
    public const float WallHeight = 3f;

    /// <summary>
    /// Builds a course of <paramref name="kind"/> in landblock (<paramref name="lbX"/>, <paramref name="lbY"/>),
    /// in the global world frame or one centred on that landblock. Its cells are turned by a random yaw
    /// (some quaternions stored slightly non-unit).
    /// </summary>
    public static BodyCourse Build(Kind kind, Random random, int lbX, int lbY, bool global)
    {
        uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
        uint prefix = id & 0xFFFF0000u;
        float floorZ = 20f + (random.NextSingle() * 60f);
        var origin = new Vector3(60f + (random.NextSingle() * 72f), 60f + (random.NextSingle() * 72f), floorZ);
        float yaw = random.Next(4) == 0 ? random.Next(4) * MathF.PI / 2 : random.NextSingle() * 2 * MathF.PI;
        Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw);
        if (random.Next(3) == 0)
        {
            q = new Quaternion(q.X, q.Y, q.Z * 1.003f, q.W * 1.003f); // stored slightly non-unit
        }

        var builders = new List<CellBuilder>();
        var areas = new List<(uint, Frame, Vector2, Vector2)>();
        CellBuilder NewCell(int index)
        {
            var b = new CellBuilder(prefix | (uint)(0x0100 + index), origin, q);
            builders.Add(b);
            return b;
        }

        void Area(CellBuilder b, float x0, float y0, float x1, float y1) =>
            areas.Add((b.CellId, b.EnvCell.Position, new Vector2(x0, y0), new Vector2(x1, y1)));

        switch (kind)
        {
            case Kind.Room:
            {
                float w = Range(random, 4, 10), d = Range(random, 4, 10);
                CellBuilder b = NewCell(0);
                Box(b, 0, 0, w, d, split: random);
                Area(b, 0, 0, w, d);
                break;
            }

            case Kind.Corridor:
            {
                float w = Range(random, 1.3f, 2.5f), l = Range(random, 8, 16);
                CellBuilder b = NewCell(0);
                Box(b, 0, 0, l, w, split: random);
                Area(b, 0, 0, l, w);
                break;
            }

            case Kind.Corners:
            {
                // An L: [0, a] × [0, b1] plus [0, c] × [b1, b]; the reflex corner at (c, b1).
                float a = Range(random, 5, 9), c = Range(random, 1.8f, a - 1.5f), b1 = Range(random, 1.8f, 5), b = b1 + Range(random, 2, 5);
                CellBuilder cell = NewCell(0);
                cell.Floor(0, 0, a, b1, 0).Floor(0, b1, c, b, 0);
                Vector2[] outline = [new(0, 0), new(a, 0), new(a, b1), new(c, b1), new(c, b), new(0, b)];
                for (int i = 0; i < outline.Length; i++)
                {
                    Vector2 p = outline[i], n = outline[(i + 1) % outline.Length];
                    cell.Physics(Wall(p.X, p.Y, n.X, n.Y, 0, WallHeight));
                }

                if (random.Next(2) == 0)
                {
                    // A diagonal wall across the far corner: two obtuse (135°) concave corners.
                    float cut = Range(random, 0.8f, 1.5f);
                    cell.Physics(Wall(a - cut, 0, a, cut, 0, WallHeight));
                }

                Area(cell, 0, 0, a, b1);
                Area(cell, 0, b1, c, b);
                break;
            }

            case Kind.Doorway:
            case Kind.DoorCell:
            {
                // Room A [0, wa] × [0, d], room B beyond it along +x, the door at y in [y0, y1], up to a top above the body.
                float wa = Range(random, 3, 7), wb = Range(random, 3, 7), d = Range(random, 3, 7);
                float width = Range(random, 0.9f, 2.5f), y0 = Range(random, 0.1f, d - width - 0.1f), y1 = y0 + width, top = Range(random, 2.0f, 2.6f);
                float gap = kind == Kind.DoorCell ? 0.4f : 0f;
                CellBuilder roomA = NewCell(0), roomB = NewCell(1);
                CellBuilder? door = gap > 0 ? NewCell(2) : null;
                ushort aNumber = (ushort)(roomA.CellId & 0xFFFF), bNumber = (ushort)(roomB.CellId & 0xFFFF);
                ushort aNext = door is null ? bNumber : (ushort)(door.CellId & 0xFFFF);
                ushort bNext = door is null ? aNumber : (ushort)(door.CellId & 0xFFFF);
                Box(roomA, 0, 0, wa, d, east: (y0, y1, top, aNext), split: random);
                if (random.Next(2) == 0)
                {
                    roomA.Physics(Opening(wa, y0, y1, top)); // a solid physics polygon in the opening, as some real doorways carry: not a wall
                }

                Box(roomB, wa + gap, 0, wa + gap + wb, d, west: (y0, y1, top, bNext), split: random);
                if (door is not null)
                {
                    door.Floor(wa, y0, wa + gap, y1, 0);
                    door.Physics(Wall(wa, y0, wa + gap, y0, 0, top)).Physics(Wall(wa + gap, y1, wa, y1, 0, top));
                    door.Physics(Ceiling(wa, y0, wa + gap, y1, top));
                    Vector3 inside = new(wa + (gap / 2), (y0 + y1) / 2, 1);
                    door.Portal(aNumber, inside, Opening(wa, y0, y1, top));
                    door.Portal(bNumber, inside, Opening(wa + gap, y0, y1, top));
                }

                Area(roomA, 0, 0, wa, d);
                Area(roomB, wa + gap, 0, wa + gap + wb, d);
                break;
            }

            case Kind.ThinWalls:
            {
                float w = Range(random, 7, 12), d = Range(random, 7, 12);
                CellBuilder b = NewCell(0);
                Box(b, 0, 0, w, d, split: random);
                for (int i = random.Next(2, 5); i > 0; i--)
                {
                    // A free-standing wall of zero thickness, one polygon, seen from both sides.
                    var c = new Vector2(Range(random, 1.5f, w - 1.5f), Range(random, 1.5f, d - 1.5f));
                    float angle = random.NextSingle() * MathF.PI, half = Range(random, 0.4f, 1.5f);
                    var along = new Vector2(MathF.Cos(angle), MathF.Sin(angle)) * half;
                    b.Physics(Wall(c.X - along.X, c.Y - along.Y, c.X + along.X, c.Y + along.Y, 0, WallHeight));
                }

                // A square pillar (four walls), a parapet to the body's waist (in its band), a curb below
                // the step height and a beam above the head (both out of the band: no obstacle).
                var pillar = new Vector2(Range(random, 1.5f, w - 1.5f), Range(random, 1.5f, d - 1.5f));
                float s = Range(random, 0.1f, 0.4f);
                Box(b, pillar.X - s, pillar.Y - s, pillar.X + s, pillar.Y + s, floor: false);
                float px = Range(random, 1, w - 3), py = Range(random, 1, d - 1);
                b.Physics(Wall(px, py, px + 2, py, 0, 1.0f));
                float cx = Range(random, 1, w - 3), cy = Range(random, 1, d - 1);
                b.Physics(Wall(cx, cy, cx + 2, cy, 0, 0.3f));
                float bx = Range(random, 1, w - 1), by = Range(random, 1, d - 3);
                b.Physics(Wall(bx, by, bx, by + 2, 2.1f, WallHeight));
                Area(b, 0, 0, w, d);
                break;
            }

            case Kind.Partition:
            {
                float w = Range(random, 6, 12), d = Range(random, 4, 9);
                CellBuilder b = NewCell(0);
                Box(b, 0, 0, w, d, split: random);
                b.Physics(Wall(w / 2, 0, w / 2, d, 0, WallHeight));
                Area(b, 0, 0, w / 2, d);
                break;
            }
        }

        string name = FormattableString.Invariant($"{kind}, yaw {yaw * 180 / MathF.PI:0.#}°");
        return Create(name, lbX, lbY, global, floorZ, builders, areas);
    }

    /// <summary>
    /// A course of the cells of <paramref name="builders"/> (floors at <paramref name="floorZ"/>) in
    /// landblock (<paramref name="lbX"/>, <paramref name="lbY"/>) over flat terrain 10 m below them, in
    /// an engine of the global frame or one centred on that landblock.
    /// </summary>
    public static BodyCourse Create(
        string name, int lbX, int lbY, bool global, float floorZ, List<CellBuilder> builders, List<(uint Cell, Frame Frame, Vector2 Min, Vector2 Max)> areas)
    {
        uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
        var terrain = new TerrainSurface(new byte[81], Enumerable.Repeat(floorZ - 10f, 256).ToArray(), id);
        PhysicsEngine engine = global ? new PhysicsEngine() : new PhysicsEngine(id);
        engine.AddLandblock(id, terrain, builders.Select(b => b.Build()).ToList());
        return new BodyCourse
        {
            Name = FormattableString.Invariant($"{name} in 0x{id:X8} ({(global ? "global" : "centred")})"),
            Engine = engine,
            LandblockId = id,
            Frame = global ? "global" : "centred",
            Origin = engine.GetLandblockOrigin(id),
            Reference = ReferenceBody.FromCells(builders.Select(b => (b.EnvCell, b.CellStruct))),
            FloorZ = floorZ,
            Areas = areas,
        };
    }

    /// <summary>
    /// A rectangular cell [x0, x1] × [y0, y1] (cell-local): its floor, unless <paramref name="floor"/> is false,
    /// and four walls; an east or west side may have a doorway (y from, y to, top, the cell beyond) with a
    /// lintel above it and a portal. With <paramref name="split"/>, each wall may be cut into collinear
    /// pieces (separate polygons meeting end to end, as real cells' walls often are).
    /// </summary>
    public static void Box(
        CellBuilder b, float x0, float y0, float x1, float y1, bool floor = true,
        (float From, float To, float Top, ushort Other)? east = null, (float From, float To, float Top, ushort Other)? west = null,
        Random? split = null)
    {
        if (floor)
        {
            b.Floor(x0, y0, x1, y1, 0);
        }

        var inside = new Vector3((x0 + x1) / 2, (y0 + y1) / 2, 1);
        Piece(x0, y0, x1, y0);
        Piece(x1, y1, x0, y1);
        Side(x1, y0, y1, east);
        Side(x0, y1, y0, west);

        void Side(float x, float from, float to, (float From, float To, float Top, ushort Other)? door)
        {
            if (door is not (float d0, float d1, float top, ushort other))
            {
                Piece(x, from, x, to);
                return;
            }

            float lo = MathF.Min(from, to), hi = MathF.Max(from, to);
            Piece(x, lo, x, d0);
            Piece(x, d1, x, hi);
            b.Physics(Wall(x, d0, x, d1, top, WallHeight));
            b.Portal(other, inside, Opening(x, d0, d1, top));
        }

        void Piece(float ax, float ay, float bx, float by)
        {
            float cut = split is not null && split.Next(2) == 0 ? Range(split, 0.2f, 0.8f) : 1f;
            float mx = ax + ((bx - ax) * cut), my = ay + ((by - ay) * cut);
            b.Physics(Wall(ax, ay, mx, my, 0, WallHeight));
            if (cut < 1f)
            {
                b.Physics(Wall(mx, my, bx, by, 0, WallHeight));
            }
        }
    }

    /// <summary>A doorway's opening in the plane x = <paramref name="x"/>, from the floor to <paramref name="top"/>.</summary>
    public static Vector3[] Opening(float x, float y0, float y1, float top) =>
        [new(x, y0, 0), new(x, y1, 0), new(x, y1, top), new(x, y0, top)];

    /// <summary>A vertical wall from (x0, y0) to (x1, y1), from z0 up to z1 (cell-local).</summary>
    public static Vector3[] Wall(float x0, float y0, float x1, float y1, float z0, float z1) =>
        [new(x0, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x0, y0, z1)];

    /// <summary>A ceiling over [x0, x1] × [y0, y1] at <paramref name="z"/>, facing down.</summary>
    public static Vector3[] Ceiling(float x0, float y0, float x1, float y1, float z) =>
        [new(x0, y0, z), new(x0, y1, z), new(x1, y1, z), new(x1, y0, z)];

    public static float Range(Random random, float min, float max) => min + (random.NextSingle() * (max - min));
}

/// <summary>
/// A doorway of the real Holtburg cells (landblock 0xA9B4, landblock-local): the cell on each side (0:
/// any outdoor cell), the opening's centre and width, its normal from <see cref="From"/> to
/// <see cref="To"/>, how far before it a walk starts, and the floor's height.
/// </summary>
internal sealed record Doorway(string Name, uint From, uint To, Vector2 Centre, Vector2 Normal, float Width, float Depth, float Floor)
{
    public override string ToString() => Name;
}

/// <summary>The real cells' doorways, and walking a body through them.</summary>
internal static class BodyDoorways
{
    /// <summary>Holtburg.</summary>
    public const uint Landblock = 0xA9B4FFFFu;

    /// <summary>The player's step height in acdream, metres.</summary>
    public const float Step = 0.6f;

    /// <summary>The doorways at floor level and at least the player's height, both ways.</summary>
    public static readonly Doorway[] Real =
    [
        new("cottage west door 0x0145, in", 0, 0xA9B40143u, new(136.5f, 5.15f), new(1, 0), 1.9f, 1.4f, 94f),
        new("cottage west door 0x0145, out", 0xA9B40143u, 0, new(136.5f, 5.15f), new(-1, 0), 1.9f, 1.4f, 94f),
        new("main room 0x0143 into the door cell 0x0144", 0xA9B40143u, 0xA9B40144u, new(136.7f, 10.47f), new(-1, 0), 5.26f, 1.1f, 94f),
        new("door cell 0x0144 into the main room 0x0143", 0xA9B40144u, 0xA9B40143u, new(136.7f, 10.47f), new(1, 0), 5.26f, 0.2f, 94f),
        new("cellar 0x0148 into its alcove 0x0149", 0xA9B40148u, 0xA9B40149u, new(128.5f, 5.5f), new(-1, 0), 8f, 1.4f, 90f),
        new("cellar alcove 0x0149 into 0x0148", 0xA9B40149u, 0xA9B40148u, new(128.5f, 5.5f), new(1, 0), 8f, 1f, 90f),
        new("building B north door 0x0170, in", 0, 0xA9B40171u, new(155.43f, 15.63f), new(0, -1), 1.905f, 1.4f, 94f),
        new("building B north door 0x0170, out", 0xA9B40171u, 0, new(155.43f, 15.63f), new(0, 1), 1.905f, 1.4f, 94f),
        new("building B door 0x0173, 0x0171 to 0x0172", 0xA9B40171u, 0xA9B40172u, new(157.93f, 8.4f), new(1, 0), 1.905f, 0.8f, 94f),
        new("building B door 0x0173, 0x0172 to 0x0171", 0xA9B40172u, 0xA9B40171u, new(157.93f, 8.4f), new(-1, 0), 1.905f, 0.8f, 94f),
    ];

    /// <summary>
    /// Doorways lower than the player: the main room and the north room through the raised door cell
    /// 0x0142 (floor 95, opening up to 96.8: 1.8 m), and the north room to the outdoors through 0x014F
    /// (floor 94.85, an arch up to 96.35: 1.5 m). The steps up to them are objects the cells lack, so a
    /// step height of 1.1 m stands in for them.
    /// </summary>
    public static readonly Doorway[] Low =
    [
        new("main room 0x0143 through 0x0142 to 0x0141", 0xA9B40143u, 0xA9B40141u, new(139.4f, 13.3f), new(0, 1), 5.4f, 1.2f, 94f),
        new("north room 0x0141 through 0x0142 to 0x0143", 0xA9B40141u, 0xA9B40143u, new(139.4f, 13.3f), new(0, -1), 5.4f, 1.2f, 94f),
        new("north room 0x0141 through 0x014F out", 0xA9B40141u, 0, new(139.4f, 19.2f), new(0, 1), 4.2f, 1.2f, 94f),
        new("outdoors through 0x014F into 0x0141", 0, 0xA9B40141u, new(139.4f, 19.2f), new(0, -1), 4.2f, 1.2f, 94f),
    ];

    /// <summary>Whether <paramref name="cell"/> is the side <paramref name="side"/> names (0: outdoors).</summary>
    public static bool IsSide(uint cell, uint side) => side == 0 ? (cell & 0xFFFF) < 0x0100 : cell == side;

    /// <summary>
    /// Walks a body through <paramref name="door"/> at <paramref name="degrees"/> from its normal, 0.15 m
    /// per frame, from a start <see cref="Doorway.Depth"/> before the opening (along the normal) and aimed
    /// at the opening's centre, or, where the from-cell's walls (<paramref name="walls"/>) leave no room
    /// for the body there, at the nearest point across the opening that does. Returns the cells visited in
    /// order and the last answer, or null when no start in the from-cell leaves the body clear of its walls
    /// at that angle.
    /// </summary>
    public static (List<uint> Cells, ResolveResult Last)? Walk(PhysicsEngine engine, ReferenceBody walls, Doorway door, float degrees, MovementOptions options, float step = Step)
    {
        MoverBody body = options.Body!.Value;
        float a = degrees * MathF.PI / 180;
        var tangent = new Vector2(-door.Normal.Y, door.Normal.X);
        Vector2 direction = (door.Normal * MathF.Cos(a)) + (tangent * MathF.Sin(a));
        Vector3 origin = engine.GetLandblockOrigin(Landblock);
        float reach = MathF.Max((door.Width / 2) - body.Radius - 0.05f, 0f);
        foreach (float across in new[] { 0f, 0.5f, -0.5f, 1f, -1f })
        {
            Vector2 aim = door.Centre + (tangent * (across * reach));
            Vector2 start = aim - (direction * (door.Depth / MathF.Cos(a)));
            var pos = origin + new Vector3(start, door.Floor);
            uint cell = door.From == 0 ? Landblock & 0xFFFF0000u : door.From;
            ResolveResult r = engine.Resolve(pos, cell, Vector3.Zero, step, options);
            double clearance = walls.Clearance(new ReferenceBody.Vec2(start.X, start.Y), door.Floor + step, door.Floor + body.Height);
            if (!r.IsOnGround || !IsSide(r.CellId, door.From) || clearance < body.Radius + 0.01)
            {
                continue; // no room for the body here
            }

            var delta = new Vector3(direction * 0.15f, 0);
            var cells = new List<uint> { r.CellId };
            for (int f = 0; f < (int)(2.2f * door.Depth / (0.15f * MathF.Cos(a))) + 4; f++)
            {
                r = engine.Resolve(r.Position, r.CellId, delta, step, options);
                if (r.CellId != cells[^1])
                {
                    cells.Add(r.CellId);
                }
            }

            return (cells, r);
        }

        return null;
    }
}
