using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Tests.Behavior;

/// <summary>Sliding along walls frame after frame, corners concave and convex, against <see cref="ReferenceBody"/>.</summary>
public class BodySlideTests
{
    private const float Step = 0.5f;

    private static readonly MovementOptions WithPlayerBody = new() { Body = MoverBody.Player };

    /// <summary>
    /// One square room of <paramref name="size"/> metres (cell-local 0..size), turned by <paramref name="yawDegrees"/>
    /// about its centre, which is at landblock-local (96, 96, 50) of landblock (<paramref name="lbX"/>, <paramref name="lbY"/>).
    /// </summary>
    internal static (BodyCourse Course, Quaternion Turn, Vector3 CellOrigin) SquareRoom(float size, float yawDegrees, int lbX, int lbY, bool global, Action<CellBuilder>? more = null)
    {
        Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yawDegrees * MathF.PI / 180);
        Vector3 cellOrigin = new Vector3(96, 96, 50) - Vector3.Transform(new Vector3(size / 2, size / 2, 0), q);
        var b = new CellBuilder(((uint)lbX << 24) | ((uint)lbY << 16) | 0x0100u, cellOrigin, q);
        BodyCourses.Box(b, 0, 0, size, size);
        more?.Invoke(b);
        BodyCourse course = BodyCourses.Create(
            FormattableString.Invariant($"{size} m room turned {yawDegrees}°"), lbX, lbY, global, 50f, [b], [(b.CellId, b.EnvCell.Position, Vector2.Zero, new Vector2(size))]);
        return (course, q, cellOrigin);
    }

    /// <summary>A cell-local point of a course built by <see cref="SquareRoom"/>, in the engine's world frame.</summary>
    internal static Vector3 World(BodyCourse course, Quaternion q, Vector3 cellOrigin, float x, float y) =>
        course.Origin + cellOrigin + Vector3.Transform(new Vector3(x, y, 0), q);

    public static TheoryData<float, int, bool> Walls() => new()
    {
        { 0f, 0xA9, false }, { 10f, 0xA9, false }, { 33f, 0xA9, false }, { 71f, 0xA9, false }, { 137.5f, 0x12, false },
        { 10f, 0xFE, true }, { 33f, 0xFE, true }, { 71f, 0xA9, true },
    };

    [Theory]
    [MemberData(nameof(Walls))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_PushingDiagonallyAlongAWallFrameAfterFrame_NeverStops(float yaw, int lb, bool global)
    {
        // A 100 m room; the mover starts 2 m off its east wall and walks at 63° into it (atan 2) for 90 m at
        // 0.1, 0.2 and 1.7 m per frame: once at the wall every frame slides along it. (Defect: the float
        // residue of the slide's projection touched the same wall again and was taken for a concave
        // corner, so most frames stopped dead at the wall.)
        foreach (float speed in new[] { 0.1f, 0.2f, 1.7f })
        {
            (BodyCourse course, Quaternion q, Vector3 cellOrigin) = SquareRoom(100, yaw, lb, lb, global);
            Vector3 pos = World(course, q, cellOrigin, 98, 2);
            uint cell = course.Areas[0].Cell;
            Vector3 delta = Vector3.Transform(Vector3.Normalize(new Vector3(1, 2, 0)), q) * speed;
            int frames = (int)(90 / (speed * 0.8944f)), slid = 0;
            for (int f = 0; f < frames; f++)
            {
                ResolveResult r = course.Engine.Resolve(pos, cell, delta, Step, WithPlayerBody);
                r.Position.Should().NotBe(pos, $"{course.Name}, {speed} m per frame, frame {f} of {frames}: stopped at {pos:R} moving {delta:R}: {r}");
                slid += r.Outcome == ResolveOutcome.Slid ? 1 : 0;
                (pos, cell) = (r.Position, r.CellId);
            }

            slid.Should().BeGreaterThan(frames * 9 / 10, $"{course.Name}, {speed} m per frame: nearly every frame slides along the wall");
        }
    }

    public static TheoryData<float, int, bool> SinkingWalls() => new()
    {
        { 10f, 0xA9, false }, { 33f, 0xA9, false }, { 71f, 0xA9, false }, { 137.5f, 0x12, false },
        { 10f, 0xFE, true }, { 33f, 0xFE, true }, { 71f, 0xA9, true }, { 0f, 0xFE, true },
    };

    [Theory]
    [MemberData(nameof(SinkingWalls))]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_AlongAWallForThousandsOfFrames_NeverSinksIntoItAndAgreesWithTheReference(float yaw, int lb, bool global)
    {
        // As above, pushing into the wall at 63°, then walking exactly along it, at 0.1, 0.2 and 1.7 m per
        // frame, each frame checked against the reference. (Defect: each answer is rounded to the world frame
        // the same way frame after frame, and nothing brought the body back, so it sank into the wall: 1 mm
        // after 350 frames in the centred frame, through its whole radius after 470 in the far global one.)
        foreach (float speed in new[] { 0.1f, 0.2f, 1.7f })
        {
            foreach (bool along in new[] { false, true })
            {
                (BodyCourse course, Quaternion q, Vector3 cellOrigin) = SquareRoom(100, yaw, lb, lb, global);
                Vector3 pos = World(course, q, cellOrigin, along ? 99.52f : 98, 2);
                uint cell = course.Areas[0].Cell;
                Vector3 delta = Vector3.Transform(Vector3.Normalize(along ? new Vector3(0, 1, 0) : new Vector3(1, 2, 0)), q) * speed;
                int frames = (int)(90 / speed);
                double deepest = double.NegativeInfinity;
                for (int f = 0; f < frames; f++)
                {
                    BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, WithPlayerBody);
                    call.Overlap.Should().BeLessThanOrEqualTo(BodyCheck.OverlapLimit, $"frame {f}: {call}");
                    call.Agrees.Should().BeTrue($"frame {f}: {call}");
                    deepest = Math.Max(deepest, call.Overlap);
                    (pos, cell) = (call.Engine.Position, call.Engine.CellId);
                }

                deepest.Should().BeLessThanOrEqualTo(0, $"{course.Name}, {speed} m per frame{(along ? " along the wall" : "")}: the skin absorbs every rounding");
            }
        }
    }

    public static TheoryData<float, int, bool> Corners() => new()
    {
        { 0f, 0xA9, false }, { 27f, 0xA9, false }, { 63.5f, 0x12, false }, { 180f, 0xA9, false },
        { 27f, 0xFE, true }, { 110f, 0xFE, true }, { 0f, 0xA9, true },
    };

    [Theory]
    [MemberData(nameof(Corners))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_PushingIntoAConcaveCorner_ComesToRestAndStaysBitForBit(float yaw, int lb, bool global)
    {
        // A 10 m room; movers from random places within 2 m of its north-east corner push at it, at
        // 0.05..2 m per frame in directions up to 30° either side of the corner's bisector: after coming to
        // rest they return the same position bit for bit frame after frame, the radius (and skin) from both walls.
        var random = new Random((int)yaw + lb);
        (BodyCourse course, Quaternion q, Vector3 cellOrigin) = SquareRoom(10, yaw, lb, lb, global);
        uint cell = course.Areas[0].Cell;
        for (int run = 0; run < 12; run++)
        {
            Vector3 pos = World(course, q, cellOrigin, BodyCourses.Range(random, 8, 9.4f), BodyCourses.Range(random, 8, 9.4f));
            float angle = (MathF.PI / 4) + BodyCourses.Range(random, -0.52f, 0.52f), length = BodyCourses.Range(random, 0.05f, 2f);
            Vector3 delta = Vector3.Transform(new Vector3(MathF.Cos(angle), MathF.Sin(angle), 0), q) * length;
            var seen = new List<ResolveResult>();
            for (int f = 0; f < 40 + (int)(8 / length); f++)
            {
                ResolveResult r = course.Engine.Resolve(pos, cell, delta, Step, WithPlayerBody);
                seen.Add(r);
                pos = r.Position;
            }

            string what = FormattableString.Invariant($"{course.Name}, run {run}: pushing by {delta:R}");
            List<ResolveResult> last = seen.TakeLast(40).ToList();
            last.Select(r => r.Position).Distinct().Should().HaveCount(1, $"{what}: at rest, bit for bit: {string.Join(", ", last.Select(r => r.Position.ToString("R", null)).Distinct())}");
            last.Should().OnlyContain(r => r.Outcome == ResolveOutcome.Wall && r.CellId == cell, $"{what}: {last[0]}");
            Vector3 local = Vector3.Transform(last[0].Position - course.Origin - cellOrigin, Quaternion.Conjugate(q));
            (10f - local.X).Should().BeInRange(0.48f - 1e-4f, 0.48f + 0.01f, $"{what}: from the east wall, at {local}");
            (10f - local.Y).Should().BeInRange(0.48f - 1e-4f, 0.48f + 0.01f, $"{what}: from the north wall, at {local}");
        }
    }

    [Theory]
    [InlineData(0f, 0xA9, false)]
    [InlineData(41f, 0xA9, false)]
    [InlineData(41f, 0xFE, true)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_PassingAThinWallsEnd_RoundsItAtTheRadiusAsTheReference(float yaw, int lb, bool global)
    {
        // A free-standing wall of zero thickness (cell-local x = 5, y 2..6). Movers walk north past its top end
        // at offsets of 0.1..0.45 m from its line (nearer than the radius), and diagonally at it: each frame
        // agrees with the reference, the body keeps its radius from the wall, and it gets past the end.
        var random = new Random(lb + (int)yaw);
        (BodyCourse course, Quaternion q, Vector3 cellOrigin) = SquareRoom(10, yaw, lb, lb, global, b => b.Physics(BodyCourses.Wall(5, 2, 5, 6, 0, BodyCourses.WallHeight)));
        uint cell = course.Areas[0].Cell;
        int rounded = 0;
        for (int run = 0; run < 16; run++)
        {
            float offset = BodyCourses.Range(random, 0.1f, 0.45f) * (run % 2 == 0 ? 1 : -1);
            Vector3 pos = World(course, q, cellOrigin, 5 + offset - (run % 4 < 2 ? 0 : 1.5f * MathF.Sign(offset)), 1);
            float speed = BodyCourses.Range(random, 0.05f, 0.6f);
            Vector3 delta = Vector3.Transform(Vector3.Normalize(new Vector3(run % 4 < 2 ? 0 : 1.5f * MathF.Sign(-offset), 5, 0)), q) * speed;
            for (int f = 0; f < (int)(7 / speed); f++)
            {
                BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, WithPlayerBody);
                call.Agrees.Should().BeTrue($"run {run}, frame {f}: {call}");
                call.Overlap.Should().BeLessThanOrEqualTo(0, $"run {run}, frame {f}: {call}");
                call.Tunnelled.Should().BeFalse($"run {run}, frame {f}: {call}");
                rounded += call.Engine.Outcome == ResolveOutcome.Slid && call.Reference.Contacts > 0 ? 1 : 0;
                pos = call.Engine.Position;
            }

            Vector3 local = Vector3.Transform(pos - course.Origin - cellOrigin, Quaternion.Conjugate(q));
            local.Y.Should().BeGreaterThan(6.2f, $"{course.Name}, run {run}: got past the wall's end (at {local})");
        }

        rounded.Should().BeGreaterThan(16, "the movers touched the wall's end and went round it");
    }

    [Theory]
    [InlineData(0f, 0xA9, false)]
    [InlineData(17f, 0xA9, false)]
    [InlineData(71f, 0x12, false)]
    [InlineData(17f, 0xFE, true)]
    [InlineData(71f, 0xFE, true)]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_AlongAWallOfCollinearPieces_StaysOnItsLineAsTheReference(float yaw, int lb, bool global)
    {
        // The east wall of a 40 m room is forty 1 m polygons end to end (as real cells' walls are cut at
        // their doors and windows). Pushing along it at 63° and walking exactly along it, at 0.2, 0.7 and
        // 1.9 m per frame, every frame agrees with the reference; pushed, the body stays on the wall's line.
        foreach (float speed in new[] { 0.2f, 0.7f, 1.9f })
        {
            foreach (bool along in new[] { false, true })
            {
                (BodyCourse course, Quaternion q, Vector3 cellOrigin) = SquareRoom(40, yaw, lb, lb, global, b =>
                {
                    for (int i = 0; i < 40; i++)
                    {
                        b.Physics(BodyCourses.Wall(39.9f, i, 39.9f, i + 1, 0, BodyCourses.WallHeight));
                    }
                });
                Vector3 pos = World(course, q, cellOrigin, along ? 39.9f - 0.4801f : 38, 1.5f);
                uint cell = course.Areas[0].Cell;
                Vector3 delta = Vector3.Transform(Vector3.Normalize(along ? new Vector3(0, 1, 0) : new Vector3(1, 2, 0)), q) * speed;
                for (int f = 0; f < (int)(35 / speed); f++)
                {
                    BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, WithPlayerBody);
                    call.Agrees.Should().BeTrue($"{speed} m per frame{(along ? " along" : "")}, frame {f}: {call}");
                    call.Overlap.Should().BeLessThanOrEqualTo(0, $"{speed} m per frame{(along ? " along" : "")}, frame {f}: {call}");
                    pos = call.Engine.Position;
                    Vector3 local = Vector3.Transform(pos - course.Origin - cellOrigin, Quaternion.Conjugate(q));
                    if (call.Engine.Outcome == ResolveOutcome.Slid && !along)
                    {
                        (39.9f - local.X).Should().BeInRange(0.48f, 0.48f + 1e-4f + (2 * (float)BodyCheck.Skin(course, pos, delta, 0.48f)) + (4 * (float)BodyCheck.Spacing(pos, delta)), $"{speed} m per frame{(along ? " along" : "")}, frame {f}: on the wall's line, at {local}");
                    }
                }
            }
        }
    }

    [Theory]
    [InlineData(0f, 0xA9, false)]
    [InlineData(33f, 0xA9, false)]
    [InlineData(200.3f, 0x77, false)]
    [InlineData(33f, 0xFE, true)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_WedgedBetweenAWallAndADoorJamb_NeverSlidesAgainstTheMoveAndAgreesWithTheReference(float yaw, int lb, bool global)
    {
        // Room A (6 × 5) has a doorway into room B in its east wall from y 0.15 to 1.15: a 0.15 m stub of
        // the east wall stands between the south wall and the door's jamb. A body pushed into that nook
        // comes to rest touching the south wall and the stub's end; pushed on at every angle from there,
        // it never moves against the push (two walls met together are resolved as one) and agrees with the
        // reference.
        Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw * MathF.PI / 180);
        var cellOrigin = new Vector3(90, 90, 50);
        uint prefix = ((uint)lb << 24) | ((uint)lb << 16);
        var roomA = new CellBuilder(prefix | 0x0100u, cellOrigin, q);
        var roomB = new CellBuilder(prefix | 0x0101u, cellOrigin, q);
        BodyCourses.Box(roomA, 0, 0, 6, 5, east: (0.15f, 1.15f, 2.3f, 0x0101));
        BodyCourses.Box(roomB, 6, 0, 9, 5, west: (0.15f, 1.15f, 2.3f, 0x0100));
        BodyCourse course = BodyCourses.Create(
            FormattableString.Invariant($"door beside a corner, yaw {yaw}°"), lb, lb, global, 50f, [roomA, roomB],
            [(roomA.CellId, roomA.EnvCell.Position, Vector2.Zero, new Vector2(6, 5))]);
        Vector3 pos = World(course, q, cellOrigin, 4.5f, 1f);
        uint cell = roomA.CellId;
        Vector3 into = Vector3.Transform(Vector3.Normalize(new Vector3(1, -0.6f, 0)), q) * 0.3f;
        for (int f = 0; f < 40; f++)
        {
            ResolveResult r = course.Engine.Resolve(pos, cell, into, Step, WithPlayerBody);
            (pos, cell) = (r.Position, r.CellId);
        }

        Vector3 nook = pos;
        int stopped = 0, slid = 0;
        for (int a = 0; a < 72; a++)
        {
            float angle = a * MathF.PI / 36;
            Vector3 delta = Vector3.Transform(new Vector3(MathF.Cos(angle), MathF.Sin(angle), 0), q) * 0.4f;
            BodyCall call = BodyCheck.Compare(course, nook, cell, delta, Step, WithPlayerBody);
            call.Agrees.Should().BeTrue($"pushed at {a * 5}° from the nook: {call}");
            call.Overlap.Should().BeLessThanOrEqualTo(0, $"pushed at {a * 5}° from the nook: {call}");
            Vector3 moved = call.Engine.Position - nook;
            Vector3.Dot(moved, delta).Should().BeGreaterThanOrEqualTo(-1e-6f, $"pushed at {a * 5}°, never against the push: {call}");
            stopped += moved == Vector3.Zero ? 1 : 0;
            slid += call.Engine.Outcome == ResolveOutcome.Slid ? 1 : 0;
        }

        stopped.Should().BeGreaterThan(0, "pushed straight into the nook, the body stays");
        slid.Should().BeGreaterThan(0, "pushed along either wall, it slides");
    }

    [Theory]
    [InlineData(17f)]
    [InlineData(52f)]
    [InlineData(128f)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Resolve_LongSweptMovesAtTheWorldsFarCorner_EndWhereThePathEnds(float yaw)
    {
        // The global frame at landblock 0xFEFE (float spacing 3.9 mm), the player's options (sub-steps of
        // 0.48 m): 5 m moves (50 m/s at 10 Hz) pushing at a wall at 63°, and along it, each frame within
        // 1 mm + 4 spacings of the reference and never into the wall. (Defect: each sub-step and path corner
        // was rounded to the world frame from the last one's rounded answer, so a 5 m move's eleven roundings
        // added up to several centimetres off its path, and into the wall.)
        foreach (bool along in new[] { false, true })
        {
            (BodyCourse course, Quaternion q, Vector3 cellOrigin) = SquareRoom(100, yaw, 0xFE, 0xFE, global: true);
            Vector3 pos = World(course, q, cellOrigin, along ? 99.5f - 0.01f : 90, 2);
            uint cell = course.Areas[0].Cell;
            Vector3 delta = Vector3.Transform(Vector3.Normalize(along ? new Vector3(0, 1, 0) : new Vector3(1, 2, 0)), q) * 5f;
            for (int f = 0; f < 18; f++)
            {
                BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, MovementOptions.Player);
                call.Overlap.Should().BeLessThanOrEqualTo(BodyCheck.OverlapLimit, $"{(along ? "along" : "into")} frame {f}: {call}");
                call.Agrees.Should().BeTrue($"{(along ? "along" : "into")} frame {f}: {call}");
                (pos, cell) = (call.Engine.Position, call.Engine.CellId);
            }
        }
    }
}
