using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Fixtures;
using AcDream.App.Scenes;
using AcDream.Core.Physics;
using AcDream.App.World;

namespace AcDream.App.Tests;

public sealed class MainJobTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "acdream-app-tests-" + Guid.NewGuid().ToString("N"));

    public MainJobTests() => Directory.CreateDirectory(_folder);

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Fact]
    public void SceneRunner_DefaultScene_VisitsTheCellsInOrder_TheCottagesCellarEnteredByAJumpBsOnFoot()
    {
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault());

        var visits = record.CellVisits();
        var indoor = visits.Select(v => CellIds.IsIndoor(v.CellId) ? v.CellId : 0u)
            .Aggregate(new List<uint>(), (list, c) => { if (list.Count == 0 || list[^1] != c) { list.Add(c); } return list; });
        indoor.Should().Equal(
            [0u, 0xA9B40145u, 0xA9B40143u, 0xA9B40147u, 0xA9B40143u, 0xA9B40145u, 0u, 0xA9B40145u, 0xA9B40143u, 0xA9B40145u, 0u,
             0xA9B40170u, 0xA9B40171u, 0xA9B40173u, 0xA9B40172u, 0xA9B40173u, 0xA9B40171u, 0xA9B40174u, 0xA9B40171u],
            $"cells visited (0 = outdoors): {string.Join(" ", visits.Select(v => $"{v.Frame}:{v.CellId:X8}"))}");
        visits.Should().Contain(v => CellIds.LandblockOf(v.CellId) == 0xA8B4FFFFu, "the walk starts west of the seam");
        record.Legs.Should().OnlyContain(l => l.Reached || l.Leg.To == null || l.Leg.Name.Contains("rock needle") || l.Leg.Name.Contains("wall") || l.Leg.Name.Contains("edge slide") || l.Leg.Name.Contains("closed door"),
            string.Join(", ", record.Legs.Where(l => !l.Reached).Select(l => l.Leg.Name)));

        // In the air only in the legs that jump (the four jumps' rises and falls); never a drop on foot.
        int[] jumpLegs = [.. record.Legs.Select((l, i) => (l, i)).Where(x => x.l.Leg.Jump).Select(x => x.i)];
        jumpLegs.Should().HaveCount(4);
        record.Samples.Where(s => !s.IsOnGround).Should().OnlyContain(
            s => jumpLegs.Any(i => s.Frame >= record.Legs[i].FirstFrame && s.Frame <= record.Legs[i].LastFrame), "airborne only while jumping");
        record.Falls().Should().HaveCount(4).And.OnlyContain(f => f.LandingFrame > 0, "every jump lands");
        record.Drops.Should().BeEmpty();

        // The cottage's cellar is entered by the jump into its floor opening and left up its stairs; B's entered and left on foot.
        foreach ((uint cellar, uint stair, uint room, bool onFoot) in new[] { (0xA9B40147u, ObjectPlacements.CottageCellarStair, 0xA9B40143u, false), (0xA9B40174u, ObjectPlacements.BuildingBCellarStair, 0xA9B40171u, true) })
        {
            int enter = visits.ToList().FindIndex(v => v.CellId == cellar);
            enter.Should().BePositive($"0x{cellar:X8} is entered");
            visits[enter - 1].CellId.Should().Be(room, "entered from the room above");
            visits[enter + 1].CellId.Should().Be(room, "and left into it");
            FrameSample[] inCellar = record.Samples.Where(s => s.Frame >= visits[enter].Frame && s.Frame < visits[enter + 1].Frame).ToArray();
            (onFoot ? inCellar : inCellar.SkipWhile(s => !s.IsOnGround)).Should().OnlyContain(s => s.IsOnGround, onFoot ? "on foot" : "on foot once landed");
            inCellar.Min(s => s.Position.Z).Should().BeLessThan(91f, "it reached the cellar floor");
            inCellar.Should().Contain(s => s.FloorObjectId == stair, "on the stair object");
        }

        record.Final.CellId.Should().Be(0xA9B40171u, "the walk ends up B's cellar stairs in its main room");
        record.Final.IsOnGround.Should().BeTrue();
        record.Final.Position.Z.Should().BeApproximately(94f, 1e-3f, "the main room's floor");
        record.Samples.Count(s => s.Slide is { Z: > 0f }).Should().BeGreaterThan(0, "the body slides along the needle's contour");
        record.Samples.Count(s => s.Slide is { Z: 0f }).Should().BeGreaterThan(0, "the body slides along the main room's east wall and the wall under 0x0142's opening");
        record.Scene.Effects.Should().Be(MovementOptions.Player, "the default scene uses the effects a player uses");
        record.Scene.Effects.Body.Should().Be(MoverBody.Player, "and so the player's body");
        record.Streaming.Count(e => e.Loaded).Should().Be(12, "9 at the start and 3 after the seam");
        record.Streaming.Count(e => !e.Loaded).Should().Be(3);
    }

    [Fact]
    public void SceneRunner_DefaultScene_SlidesAndRefusalsAreTheEnginesOutcomesPerLegAndInTheSummary()
    {
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault());
        string Slides(int leg) => string.Join(" ", record.Legs[leg - 1].Slides);

        // Leg 2 runs at the rock needle: with walkable slope and a body the engine slides it along the
        // slope's contour (the slope's normal, which has a Z) instead of refusing it.
        LegResult needle = record.Legs[1];
        needle.Leg.Name.Should().Contain("rock needle");
        needle.Reached.Should().BeFalse();
        needle.Refusals.Should().BeEmpty();
        needle.Slides.Should().HaveCountGreaterThan(50, $"the leg runs 4 s into the slope; {Slides(2)}")
            .And.OnlyContain(n => n.Z > 0.05f && n.Z < PhysicsConstants.FloorZ, "a slope too steep to climb");

        // Legs 12 and 13 slide along the main room's east wall and the wall under the opening to 0x0142.
        LegResult east = record.Legs[11], north = record.Legs[12];
        east.Leg.Name.Should().Contain("east wall");
        east.Slides.Should().HaveCountGreaterThan(20, Slides(12)).And.OnlyContain(n => MathF.Abs(n.X + 1f) < 1e-4f && MathF.Abs(n.Y) < 1e-4f && n.Z == 0f, "the east wall's normal points west");
        north.Leg.Name.Should().Contain("0x0142");
        north.Slides.Should().HaveCountGreaterThan(20, Slides(13)).And.OnlyContain(n => MathF.Abs(n.X) < 1e-4f && MathF.Abs(n.Y + 1f) < 1e-4f && n.Z == 0f, "the wall under the opening faces south");

        // The body slides where the point was refused; only the closed west door, walked at head on from inside and
        // from outside, refuses it (as a wall).
        LegResult[] atDoor = [.. record.Legs.Where(l => l.Leg.Name.Contains("at the closed door"))];
        atDoor.Should().HaveCount(2);
        atDoor.Should().OnlyContain(l => l.Refusals.Count == 1 && l.Refusals.GetValueOrDefault(ResolveOutcome.Wall) > 10,
            string.Join("; ", atDoor.Select(l => $"{l.Leg.Name}: {string.Join(", ", l.Refusals)}")));
        record.Legs.Except(atDoor).Should().OnlyContain(l => l.Refusals.Count == 0, string.Join("; ", record.Legs.Where(l => l.Refusals.Count > 0).Select(l => l.Leg.Name)));
        int doorWalls = atDoor.Sum(l => l.Refusals[ResolveOutcome.Wall]);

        string summary = WalkReport.Format(record, "walk.svg");
        string[] lines = summary.Split(System.Environment.NewLine);
        lines.Should().ContainSingle(l => l.StartsWith("   2. run at the rock needle", StringComparison.Ordinal))
            .Which.Should().EndWith($"; slid {needle.Slides.Count} × along a slope's contour, normal ({needle.Slides[0].X:F2}, {needle.Slides[0].Y:F2}, {needle.Slides[0].Z:F2})", summary);
        lines.Should().ContainSingle(l => l.StartsWith("  12. ", StringComparison.Ordinal)).Which.Should().EndWith($"; slid {east.Slides.Count} × along a wall, normal (-1.00, 0.00)", summary);
        lines.Should().ContainSingle(l => l.StartsWith("  13. ", StringComparison.Ordinal)).Which.Should().EndWith($"; slid {north.Slides.Count} × along a wall, normal (0.00, -1.00)", summary);
        int wallSlides = record.Samples.Count(s => s.Slide is { Z: 0f });
        lines.Should().ContainSingle(l => l.StartsWith("Slid moves: ", StringComparison.Ordinal)).Which.Should().Be(
            $"Slid moves: {wallSlides} along walls, {record.SlideCount - wallSlides} along slopes' contours.", summary);
        wallSlides.Should().BeGreaterThan(east.Slides.Count + north.Slides.Count - 1);
        lines.Should().ContainSingle(l => l.StartsWith("Refused moves: ", StringComparison.Ordinal)).Which.Should().Be(
            $"Refused moves: 0 step too high (> 0.6 m), 0 slope too steep, {doorWalls} wall, 0 outer wall, 0 unloaded land ahead, 0 edge of the world, 0 held at an edge.");
        lines.Should().Contain(l => l.StartsWith("Effects: ", StringComparison.Ordinal) && l.Contains("a body (an upright cylinder of radius 0.48 m, 1.835 m tall)"), summary);
    }

    [Fact]
    public void SceneRunner_DefaultScene_JumpsMeetTheCeilingLandInTheCellarAndOnThePlinthAndEdgeSlide()
    {
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault());
        LegResult Leg(string start) => record.Legs.Single(l => l.Leg.Name.StartsWith(start, StringComparison.Ordinal));
        FrameSample[] Frames(LegResult leg) => record.Samples.Where(s => s.Frame >= leg.FirstFrame && s.Frame <= leg.LastFrame).ToArray();

        // The jump in the main room: the head meets its ceiling (96.8 m) once, never above it, and the player lands in the room.
        LegResult room = Leg("jump in the main room");
        room.Air.Should().Be((1, 1, 1, 0), "one jump, one head hit, one landing");
        Frames(room).Should().OnlyContain(s => s.CellId == 0xA9B40143u && s.Position.Z + MoverBody.Player.Height <= 96.801f, "in the room, under its ceiling");
        Frames(room)[^1].Position.Z.Should().Be(94f);

        // The running jump into the floor opening lands on the cellar's floor (90.95 m) in 0x0147.
        LegResult drop = Leg("running jump east into the floor opening");
        drop.Reached.Should().BeTrue();
        drop.Air.Should().Be((1, 1, 1, 0));
        FrameSample landed = Frames(drop)[^1];
        (landed.CellId, landed.Position.Z, landed.IsOnGround).Should().Be((0xA9B40147u, 90.95f, true), "on the cellar's floor");

        // The jump onto the plinth from beside it lands on its top (96 m); along its edge, edge slide keeps the player on it.
        LegResult plinth = Leg("jump onto the plinth from beside it");
        plinth.Air.Jumps.Should().Be(1);
        (Frames(plinth)[^1].Position.Z, Frames(plinth)[^1].IsOnGround).Should().Be((96f, true), "on the plinth");
        LegResult edge = Leg("along the plinth's east edge");
        edge.Air.EdgeSlides.Should().BeGreaterThan(30);
        Frames(edge).Should().OnlyContain(s => s.IsOnGround && s.Position.Z == 96f, "never off the plinth");

        string[] lines = WalkReport.Format(record, "walk.svg").Split(System.Environment.NewLine);
        (int jumps, int headHits, int landings, int edgeSlides) = record.Air;
        lines.Should().Contain($"Jumps: {jumps}; head hits: {headHits}; landings: {landings}; edge slides (held at a floor's edge): {edgeSlides}.");
        jumps.Should().Be(4);
    }

    [Fact]
    public void SceneRunner_DefaultScene_EastWallLegSlidesNorthAlongTheWallItsRadiusAway()
    {
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault());
        LegResult leg = record.Legs.Single(l => l.Leg.Name.StartsWith("diagonally into the main room's east wall", StringComparison.Ordinal));
        const float wallX = 142.1f; // the main room 0x0143's east wall, landblock-local = world here
        FrameSample[] frames = record.Samples.Where(s => s.Frame >= leg.FirstFrame - 1 && s.Frame <= leg.LastFrame).ToArray();

        // The leg walks from (139, 10) towards (152, 16), 24.8° from the wall's normal: diagonally at it.
        Vector2 start = new(frames[0].Position.X, frames[0].Position.Y);
        Vector2 aim = Vector2.Normalize(leg.Leg.To!.Value - start);
        MathF.Acos(aim.X).Should().BeInRange(0.35f, 0.5f, $"the leg aims {aim} at the wall, 20–29° from its normal (−1, 0)");

        foreach (FrameSample s in frames)
        {
            (wallX - s.Position.X).Should().BeGreaterThanOrEqualTo(MoverBody.Player.Radius - 1e-3f, $"frame {s.Frame}: the body stays its radius off the wall, at {s.Position}");
            s.CellId.Should().Be(0xA9B40143u, $"frame {s.Frame}");
            s.Position.Z.Should().Be(94f, $"frame {s.Frame}");
        }

        FrameSample[] sliding = frames.Where(s => s.Slide is not null).ToArray();
        sliding.Should().HaveCountGreaterThan(20);
        sliding.Should().OnlyContain(s => MathF.Abs(s.Position.X - (wallX - MoverBody.Player.Radius)) < 1e-3f, "in contact while it slides");
        for (int i = 1; i < sliding.Length; i++)
        {
            sliding[i].Position.Y.Should().BeGreaterThan(sliding[i - 1].Position.Y, $"frame {sliding[i].Frame}: it moves north along the wall");
        }

        (sliding[^1].Position.Y - sliding[0].Position.Y).Should().BeGreaterThan(0.5f, $"slid from {sliding[0].Position} to {sliding[^1].Position}");
        leg.Reached.Should().BeFalse("its point is beyond the wall");
    }

    [Fact]
    public void SceneRunner_DefaultScene_DoorwayLegsPassTheWestDoorAtFortyFiveDegrees()
    {
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault());
        var jamb = new Vector2(136.7f, 6.1f); // the west door 0x0145's north jamb on the main room's side

        int into = record.Legs.ToList().FindIndex(l => l.Leg.Name.StartsWith("in through the door's two doorways at 45°", StringComparison.Ordinal));
        into.Should().BePositive();
        foreach ((int index, uint[] cells) in new[] { (into, new[] { 0xA9B40029u, 0xA9B40145u, 0xA9B40143u }), (into + 1, new[] { 0xA9B40143u, 0xA9B40145u, 0xA9B40029u }) })
        {
            LegResult leg = record.Legs[index];
            FrameSample[] frames = record.Samples.Where(s => s.Frame >= leg.FirstFrame - 1 && s.Frame <= leg.LastFrame).ToArray();
            var visited = new List<uint>();
            foreach (FrameSample s in frames)
            {
                if (visited.Count == 0 || visited[^1] != s.CellId)
                {
                    visited.Add(s.CellId);
                }

                Vector2.Distance(new Vector2(s.Position.X, s.Position.Y), jamb).Should().BeGreaterThanOrEqualTo(MoverBody.Player.Radius - 1e-3f, $"leg {index + 1} frame {s.Frame}: the body stays off the jamb, at {s.Position}");
            }

            Vector2 start = new(frames[0].Position.X, frames[0].Position.Y);
            Vector2 aim = Vector2.Normalize(leg.Leg.To!.Value - start);
            (MathF.Acos(MathF.Abs(aim.X)) * 180f / MathF.PI).Should().BeApproximately(45f, 0.5f, $"leg {index + 1} aims {aim}, 45° from the doorways' normal (±1, 0)");
            leg.Reached.Should().BeTrue($"leg {index + 1} passes both doorways");
            visited.Should().Equal(cells, $"leg {index + 1} ({leg.Leg.Name}) cells: {string.Join(" ", visited.Select(c => c.ToString("X8")))}");
            leg.Slides.Should().NotBeEmpty($"leg {index + 1} rounds the jamb").And.OnlyContain(n => n.Z == 0f && n.X > 0f && n.Y < 0f, "the jamb's corner pushes the body east and south");
        }
    }

    [Fact]
    public void SceneRunner_LiteralEffects_ShaftIsAOneFrameDrop()
    {
        // Building B's cellar shaft without its stair: the literal engine drops the mover onto the cellar floor.
        Scene scene = SceneReader.Parse("""
            { "name": "shaft", "start": { "position": [155.43, 23] }, "objects": ["cottage"],
              "legs": [ { "name": "in", "to": [155.43, 12] }, { "name": "east", "to": [156.5, 8.4] }, { "name": "over the shaft", "to": [153.9, 8.4] } ] }
            """, "test");
        WalkRecord record = SceneRunner.Run(scene);

        record.Drops.Should().ContainSingle(d => d.ToCellId == 0xA9B40174u && d.FromZ - d.ToZ > 3.9f);
        record.AirborneFrames.Should().Be(0, "the literal engine always snaps to the ground");
        record.Final.CellId.Should().Be(0xA9B40174u);
    }

    [Theory]
    [InlineData("\"player\"", 1.5f, true, 0.48f, true, 0.48f, 1.835f, true)]
    [InlineData("{ \"body\": \"player\", \"vertical\": true, \"footing\": true, \"edgeSlide\": true }", null, false, null, false, 0.48f, 1.835f, true)]
    [InlineData("\"literal\"", null, false, null, false, null, null)]
    [InlineData("{ \"stepDownHeight\": 2, \"doorsOnly\": true }", 2f, false, null, true, null, null)]
    [InlineData("{ \"walkableSlope\": true, \"sweepStepLength\": 0.3 }", null, true, 0.3f, false, null, null)]
    [InlineData("{ \"doorsOnly\": true, \"body\": \"player\" }", null, false, null, true, 0.48f, 1.835f)]
    [InlineData("{ \"body\": { \"radius\": 0.3, \"height\": 1.2 } }", null, false, null, false, 0.3f, 1.2f)]
    [InlineData("{ \"body\": { \"height\": 100, \"radius\": 10 } }", null, false, null, false, 10f, 100f)]
    [InlineData("{ \"walkableSlope\": true, \"body\": null }", null, true, null, false, null, null)]
    public void SceneReader_Effects_ReadAsMovementOptions(string effects, float? stepDown, bool slope, float? sweep, bool doors, float? radius, float? height, bool threeD = false)
    {
        Scene scene = SceneReader.Parse($$"""{ "name": "t", "start": { "position": [10, 10] }, "effects": {{effects}}, "legs": [ { "name": "a", "to": [11, 10] } ] }""", "test.json");
        MoverBody? body = radius is float r && height is float h ? new MoverBody(r, h) : null;
        var expected = new MovementOptions { StepDownHeight = stepDown, WalkableSlope = slope, SweepStepLength = sweep, DoorsOnly = doors, Body = body, Vertical = threeD, Footing = threeD, EdgeSlide = threeD };
        scene.Effects.Should().Be(expected, $"effects {effects}");
    }

    [Theory]
    [InlineData("\"fast\"", "effects")]
    [InlineData("{ \"stepDownHeight\": -1 }", "effects.stepDownHeight")]
    [InlineData("{ \"sweepStepLength\": 0 }", "effects.sweepStepLength")]
    [InlineData("{ \"gravity\": 3 }", "effects")]
    [InlineData("{ \"body\": \"giant\" }", "effects.body")]
    [InlineData("{ \"body\": { \"radius\": 0.5 } }", "effects.body.height")]
    public void SceneReader_BadEffects_NameTheField(string effects, string field)
    {
        FluentActions.Invoking(() => SceneReader.Parse($$"""{ "name": "t", "start": { "position": [10, 10] }, "effects": {{effects}}, "legs": [ { "name": "a", "to": [11, 10] } ] }""", "bad.json"))
            .Should().Throw<SceneFormatException>().WithMessage($"*bad.json*{field}*");
    }

    [Fact]
    public void SceneReader_Pointers_ReadInOrder()
    {
        Scene scene = SceneReader.Parse("""
            { "name": "t", "start": { "position": [10, 10] }, "legs": [ { "name": "a", "to": [11, 10] }, { "name": "b", "to": [12, 10] } ],
              "pointers": [ { "name": "down", "afterLeg": 2, "from": [10, 10, 5], "towards": [12, 10, 0] }, { "name": "east", "afterLeg": 1, "from": [-200, 300, 1e2], "towards": [0, 0, 0] } ] }
            """, "test.json");

        scene.Pointers.Should().Equal([new ScenePointer("down", 2, new Vector3(10, 10, 5), new Vector3(12, 10, 0)), new ScenePointer("east", 1, new Vector3(-200, 300, 100), Vector3.Zero)]);
        SceneReader.Parse("""{ "name": "t", "start": { "position": [10, 10] }, "legs": [ { "name": "a", "to": [11, 10] } ] }""", "test.json").Pointers.Should().BeEmpty();
    }

    [Theory]
    [InlineData("""{ "name": "p", "afterLeg": 1, "from": [1, 2, 3] }""", "pointers[0].towards", "is missing")]
    [InlineData("""{ "name": "p", "afterLeg": 2, "from": [1, 2, 3], "towards": [4, 5, 6] }""", "pointers[0].afterLeg", "between 1 and 1")]
    [InlineData("""{ "name": "p", "afterLeg": 0.5, "from": [1, 2, 3], "towards": [4, 5, 6] }""", "pointers[0].afterLeg", "between 1 and 1")]
    [InlineData("""{ "name": "p", "from": [1, 2, 3], "towards": [4, 5, 6] }""", "pointers[0].afterLeg", "is missing")]
    [InlineData("""{ "name": "p", "afterLeg": 1, "from": [1, 2], "towards": [4, 5, 6] }""", "pointers[0].from", "[x, y, z]")]
    [InlineData("""{ "name": "p", "afterLeg": 1, "from": [1, 2, 3], "towards": [1, 2, 3] }""", "pointers[0].towards", "must differ")]
    [InlineData("""{ "name": "p", "afterLeg": 1, "from": [5000, 2, 3], "towards": [1, 2, 3] }""", "pointers[0].from", "within 384 m")]
    [InlineData("""{ "name": "", "afterLeg": 1, "from": [1, 2, 3], "towards": [4, 5, 6] }""", "pointers[0].name", "non-empty")]
    [InlineData("""{ "name": "p", "afterLeg": 1, "from": [1, 2, 3], "towards": [4, 5, 6], "radius": 1 }""", "pointers[0].radius", "unknown field")]
    [InlineData("\"p\"", "pointers[0]", "JSON object")]
    public void SceneReader_BadPointer_NamesTheField(string pointer, string field, string problem)
    {
        FluentActions.Invoking(() => SceneReader.Parse($$"""{ "name": "t", "start": { "position": [10, 10] }, "legs": [ { "name": "a", "to": [11, 10] } ], "pointers": [ {{pointer}} ] }""", "bad.json"))
            .Should().Throw<SceneFormatException>().WithMessage($"bad.json: field {field}: *{problem}*");
    }

    [Fact]
    public void Run_NoArguments_PrintsSummaryAndWritesAWellFormedSvg()
    {
        var output = new StringWriter();
        var error = new StringWriter();

        int status = MainJob.Run(["--out", _folder], output, error);

        status.Should().Be(0, error.ToString());
        string svg = Path.Combine(_folder, "holtburg-walk.svg");
        output.ToString().Should().Contain($"SVG: {svg}").And.Contain("Cells visited").And.Contain("0xA9B40174").And.Contain("stairs").And.Contain("Refused moves")
            .And.Contain("Camera: a chase camera").And.Contain("Camera pulled in, per leg").And.Contain("Pointer rays (radius 0, at most 100 m");
        XDocument document = XDocument.Load(svg);
        XNamespace ns = "http://www.w3.org/2000/svg";
        document.Root!.Name.Should().Be(ns + "svg");
        document.Descendants(ns + "polyline").Count().Should().BeGreaterThan(20, "the route, one line per cell run, on the map and on the profile");
        document.Descendants(ns + "path").Should().NotBeEmpty("terrain contours");
        document.Descendants(ns + "g").Select(g => (string?)g.Attribute("id")).Should().Contain(["map", "profile", "floor-plans", "contours", "body-clearance"]);
        document.Descendants(ns + "polyline").Count(l => (string?)l.Attribute("class") == "camera-eye").Should().Be(2, "the eye's path on the map and its Z in the profile");
    }

    [Fact]
    public void Run_RepositoryExampleScene_GivesTheSameWalkAsTheDefault()
    {
        string file = Path.Combine(TestWorlds.RepositoryRoot(), "src", "AcDream.App", "Scenes", "holtburg-walk.json");
        var output = new StringWriter();

        MainJob.Run(["--scene", file, "--out", _folder, "--quiet"], output, new StringWriter()).Should().Be(0);

        output.ToString().Trim().Should().Be($"SVG: {Path.Combine(_folder, "holtburg-walk.svg")}", "--quiet prints only the path");
        WalkRecord fromFile = SceneRunner.Run(SceneReader.ReadFile(file), 400);
        WalkRecord embedded = SceneRunner.Run(SceneReader.ReadDefault(), 400);
        fromFile.Samples.Should().Equal(embedded.Samples);
        fromFile.Truncated.Should().BeTrue();
        fromFile.Final.Frame.Should().Be(400, "--frames stops the walk");
    }

    [Theory]
    [InlineData("""{"name": "x", "start": {"position": [0, 0]}, "legs": [{"name": "a", "to": [1, "two"]}]}""", "legs[0].to", "[1, \"two\"]")]
    [InlineData("""{"name": "x", "start": {"position": [0, 0]}, "legs": [{"name": "a", "forward": 3, "seconds": 1}]}""", "legs[0].forward", "3")]
    [InlineData("""{"name": "x", "start": {"position": [0, 0]}, "legs": [{"name": "a", "turn": 1}]}""", "legs[0].seconds", "\"turn\"")]
    [InlineData("""{"name": "x", "start": {"position": [0, 0]}, "legs": [], "speed": 2}""", "speed", "2")]
    [InlineData("""{"name": "x", "start": {"position": [5000, 0]}, "legs": [{"name": "a", "to": [1, 2]}]}""", "start.position", "[5000, 0]")]
    [InlineData("""{"name": "x", "legs": [{"name": "a", "to": [1, 2]}]}""", "start", "is missing")]
    public void Run_BadSceneFile_ExitsTwoNamingFileFieldAndValue(string json, string field, string value)
    {
        string file = Path.Combine(_folder, "bad.json");
        File.WriteAllText(file, json);
        var error = new StringWriter();

        int status = MainJob.Run(["--scene", file, "--out", _folder], new StringWriter(), error);

        status.Should().Be(2);
        error.ToString().Should().Contain(file).And.Contain($"field {field}:").And.Contain(value);
        File.Exists(Path.Combine(_folder, "x.svg")).Should().BeFalse("nothing runs on a bad scene");
    }

    [Theory]
    [InlineData("""{ "radius": -0.48, "height": 1.835 }""", "effects.body.radius", "between 0 (exclusive) and 10", "-0.48")]
    [InlineData("""{ "radius": 0, "height": 1.835 }""", "effects.body.radius", "between 0 (exclusive) and 10", "0")]
    [InlineData("""{ "radius": 0.48, "height": 0 }""", "effects.body.height", "between 0 (exclusive) and 100", "0")]
    [InlineData("""{ "radius": 0.48, "height": -2 }""", "effects.body.height", "between 0 (exclusive) and 100", "-2")]
    [InlineData("""{ "radius": "NaN", "height": 1.835 }""", "effects.body.radius", "must be a number", "\"NaN\"")]
    [InlineData("""{ "radius": 0.48, "height": 1e39 }""", "effects.body.height", "must be a number", "1e39")]
    [InlineData("""{ "radius": 11, "height": 1.835 }""", "effects.body.radius", "between 0 (exclusive) and 10", "11")]
    [InlineData("""{ "radius": 0.48 }""", "effects.body.height", "is missing", "nothing")]
    [InlineData("""{ "radius": 0.48, "height": 1.8, "shape": "capsule" }""", "effects.body.shape", "unknown field", "\"capsule\"")]
    [InlineData(""" "tall" """, "effects.body", "must be \"player\", null (a point) or", "\"tall\"")]
    [InlineData("3", "effects.body", "must be \"player\", null (a point) or", "3")]
    public void Run_BadBodyInSceneFile_ExitsTwoWithOneLineNamingFieldAndValue(string body, string field, string problem, string value)
    {
        string file = Path.Combine(_folder, "body.json");
        File.WriteAllText(file, $$"""{ "name": "x", "start": { "position": [10, 10] }, "effects": { "doorsOnly": true, "body": {{body}} }, "legs": [ { "name": "a", "to": [11, 10] } ] }""");
        var error = new StringWriter();

        int status = MainJob.Run(["--scene", file, "--out", _folder], new StringWriter(), error);

        status.Should().Be(2, error.ToString());
        string[] lines = error.ToString().Split(System.Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
        lines.Should().ContainSingle($"one line: {error}");
        lines[0].Should().StartWith($"error: scene {file}: field {field}: ").And.Contain(problem).And.EndWith($"; got {value}");
        File.Exists(Path.Combine(_folder, "x.svg")).Should().BeFalse("nothing runs on a bad scene");
    }

    [Fact]
    public void Run_SceneRunningEastToTheEdgeOfTheWorld_WritesItsSvgOverTheEarlierOne()
    {
        // Seven 600 s runs east from the easternmost start allowed: the mover reaches the world's east
        // edge (0xFE, x = 16,512 m) and the map, padded 15 m, reaches past it.
        string legs = string.Join(", ", Enumerable.Range(1, 7).Select(i => $$"""{ "name": "east {{i}}", "forward": 1, "run": true, "seconds": 600 }"""));
        string file = Path.Combine(_folder, "east.json");
        File.WriteAllText(file, $$"""{ "name": "east edge", "start": { "position": [480, 96], "heading": 90 }, "legs": [ {{legs}} ] }""");
        string svg = Path.Combine(_folder, "east-edge.svg");
        File.WriteAllText(svg, "<svg>an earlier result</svg>");
        var output = new StringWriter();
        var error = new StringWriter();

        int status = MainJob.Run(["--scene", file, "--out", _folder], output, error);

        status.Should().Be(0, $"a valid scene runs; error: {error}");
        output.ToString().Should().MatchRegex(@"Final: \(165\d\d\.\d\d, 96\.\d\d, [-\d.]+\) m in 0xFEB4", $"the walk ends at the east edge:\n{output}");
        XDocument document = XDocument.Load(svg);
        XNamespace ns = "http://www.w3.org/2000/svg";
        document.Descendants(ns + "g").Select(g => (string?)g.Attribute("id")).Should().Contain(["map", "contours"]);
        document.Descendants(ns + "path").Should().NotBeEmpty("terrain contours up to the edge");
        Directory.GetFiles(_folder).Select(Path.GetFileName).Should().BeEquivalentTo(["east.json", "east-edge.svg", "east-edge.html"], "no temporary file is left behind (the SVG and the page beside it)");
    }

    [Fact]
    public void WriteAtomically_WriterFails_LeavesTheEarlierFileAndNoTemporaryFile()
    {
        string path = Path.Combine(_folder, "walk.svg");
        File.WriteAllText(path, "earlier");

        FluentActions.Invoking(() => MainJob.WriteAtomically(path, stream =>
        {
            stream.Write("half a new fi"u8);
            throw new InvalidOperationException("the writer failed");
        })).Should().Throw<InvalidOperationException>();

        File.ReadAllText(path).Should().Be("earlier", "a failed write does not touch the earlier result");
        Directory.GetFiles(_folder).Select(Path.GetFileName).Should().Equal(["walk.svg"], "the temporary file is removed");
        MainJob.WriteAtomically(path, stream => stream.Write("new"u8));
        File.ReadAllText(path).Should().Be("new", "a write that succeeds replaces the file");
        Directory.GetFiles(_folder).Select(Path.GetFileName).Should().Equal(["walk.svg"]);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Run_SceneFileLargerThanOneMebibyte_ExitsTwoNamingTheFileAndTheLimit(bool devZero)
    {
        string file = devZero ? "/dev/zero" : Path.Combine(_folder, "big.json");
        if (!devZero)
        {
            // A valid scene of 2 MiB (a long note): only its size is wrong.
            string note = new('a', 2 * 1024 * 1024);
            File.WriteAllText(file, $$"""{ "name": "big", "start": { "position": [10, 10] }, "legs": [ { "name": "a", "to": [11, 10] } ], "notes": ["{{note}}"] }""");
        }
        else if (!File.Exists(file))
        {
            return; // no /dev/zero on this system
        }

        var error = new StringWriter();

        int status = MainJob.Run(["--scene", file, "--out", _folder], new StringWriter(), error);

        status.Should().Be(2, error.ToString());
        string[] lines = error.ToString().Split(System.Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
        lines.Should().ContainSingle($"one line: {error}");
        lines[0].Should().Contain(file).And.Contain("1 MiB", lines[0]);
        File.Exists(Path.Combine(_folder, "big.svg")).Should().BeFalse("nothing runs");
    }

    [Fact]
    public void Run_SceneFileOfExactlyOneMebibyte_IsRead()
    {
        string file = Path.Combine(_folder, "full.json");
        string scene = """{ "name": "full", "start": { "position": [10, 10] }, "legs": [ { "name": "a", "to": [11, 10] } ] }""";
        File.WriteAllText(file, scene + new string(' ', SceneReader.MaxFileBytes - scene.Length));
        new FileInfo(file).Length.Should().Be(SceneReader.MaxFileBytes);

        int status = MainJob.Run(["--scene", file, "--out", _folder, "--quiet"], new StringWriter(), new StringWriter());

        status.Should().Be(0, "the limit itself is allowed");
        File.Exists(Path.Combine(_folder, "full.svg")).Should().BeTrue();
    }

    [Theory]
    [InlineData("""{"name": "x", "name": "y", "start": {"position": [0, 0]}, "legs": [{"name": "a", "to": [1, 2]}]}""", "name", "\"y\"")]
    [InlineData("""{"name": "x", "start": {"position": [0, 0], "heading": 10, "heading": 20}, "legs": [{"name": "a", "to": [1, 2]}]}""", "start.heading", "20")]
    [InlineData("""{"name": "x", "start": {"position": [0, 0]}, "legs": [{"name": "a", "to": [1, 2], "to": [3, 4]}]}""", "legs[0].to", "[3, 4]")]
    [InlineData("""{"name": "x", "start": {"position": [0, 0]}, "effects": {"doorsOnly": true, "doorsOnly": false}, "legs": [{"name": "a", "to": [1, 2]}]}""", "effects.doorsOnly", "false")]
    public void Run_DuplicateKeyInSceneFile_ExitsTwoNamingTheKey(string json, string field, string value)
    {
        string file = Path.Combine(_folder, "twice.json");
        File.WriteAllText(file, json);
        var error = new StringWriter();

        int status = MainJob.Run(["--scene", file, "--out", _folder], new StringWriter(), error);

        status.Should().Be(2, error.ToString());
        error.ToString().Should().Contain(file).And.Contain($"field {field}:").And.Contain("twice").And.Contain(value);
        File.Exists(Path.Combine(_folder, "x.svg")).Should().BeFalse("nothing runs on a bad scene");
    }

    [Fact]
    public void Run_SceneFileNotJson_ExitsTwoWithTheLine()
    {
        string file = Path.Combine(_folder, "broken.json");
        File.WriteAllText(file, "{\n  \"name\": \"x\",\n  oops\n}");
        var error = new StringWriter();

        MainJob.Run(["--scene", file], new StringWriter(), error).Should().Be(2);

        error.ToString().Should().Contain(file).And.Contain("not valid JSON").And.Contain("line 3");
    }

    [Fact]
    public void Run_MissingSceneFile_ExitsTwo()
    {
        string file = Path.Combine(_folder, "nowhere.json");
        var error = new StringWriter();

        MainJob.Run(["--scene", file], new StringWriter(), error).Should().Be(2);

        error.ToString().Should().Contain(file).And.Contain("cannot read");
    }

    [Theory]
    [InlineData(new[] { "--bogus" }, "\"--bogus\"")]
    [InlineData(new[] { "--frames", "abc" }, "\"abc\"")]
    [InlineData(new[] { "--frames", "0" }, "\"0\"")]
    [InlineData(new[] { "--scene" }, "--scene needs a value")]
    public void Run_BadOption_ExitsTwoNamingIt(string[] args, string named)
    {
        var error = new StringWriter();

        MainJob.Run(args, new StringWriter(), error).Should().Be(2);

        error.ToString().Should().Contain(named).And.Contain("--help");
    }

    [Fact]
    public void Run_Help_PrintsUsageAndExitsZero()
    {
        var output = new StringWriter();

        MainJob.Run(["--help"], output, new StringWriter()).Should().Be(0);

        output.ToString().Should().Contain("Usage:").And.Contain("--scene FILE").And.Contain("--frames N").And.Contain("--quiet");
    }
}
