// PhysicsEngine.cs names the mover registry by its former name (its field, constructor call and property type);
// the alias goes once that file says MoverRegistry.
global using Movers = AcDream.Core.Physics.MoverRegistry;
